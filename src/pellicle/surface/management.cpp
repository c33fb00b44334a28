#include "pellicle/surface/management.hpp"

#include <stdexcept>
#include <string>

#include "pellicle/surface/management_steps.hpp"

namespace pellicle {

template <int D>
ManagementReport manage_points(PointCloud<D>& cloud, NeighbourSearch<D>& search,
                               const ManagementOptions& options, const FrameOptions& frames) {
  if (!(options.r_min > 0.0) || !(options.r_max > options.r_min))
    throw std::invalid_argument(
        "point management needs 0 < r_min < r_max, found r_min = " + std::to_string(options.r_min) +
        ", r_max = " + std::to_string(options.r_max));
  ManagementReport report;
  if (cloud.size() == 0) return report;
  // Merging first: the filling keeps every new point r_min h from all others, so it cannot
  // undo the merging, while merging can open small holes the filling then closes.
  merge_close_points(cloud, search, options, frames.weight_exponent, report);
  fill_holes(cloud, search, options, frames.weight_exponent, report);
  return report;
}

template ManagementReport manage_points<2>(PointCloud<2>&, NeighbourSearch<2>&,
                                           const ManagementOptions&, const FrameOptions&);
template ManagementReport manage_points<3>(PointCloud<3>&, NeighbourSearch<3>&,
                                           const ManagementOptions&, const FrameOptions&);

}  // namespace pellicle
