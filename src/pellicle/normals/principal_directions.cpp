#include "pellicle/normals/principal_directions.hpp"

#include <algorithm>
#include <cmath>

#include "pellicle/pointcloud/weighted_moments.hpp"
#include "pellicle/pointcloud/weights.hpp"

namespace pellicle {

namespace {

constexpr double kSpacings = 3.0;   //!< neighbourhood radius in nearest-neighbour spacings
constexpr double kMostCells = 1.5;  //!< and at most this many cells

}  // namespace

template <int D>
double median_spacing(const std::vector<Vec<D>>& x, double search) {
  const long n = static_cast<long>(x.size());
  const CellGroups<D> groups(x, 0, n, Vec<D>::Zero(), search);
  std::vector<double> nearest;
  nearest.reserve(n);
  for (long p = 0; p < n; ++p) {
    double best = search * search;
    bool found = false;
    groups.for_each_around(groups.cell_of(x[p]), [&](int g) {
      for (const long* q = groups.begin(g); q != groups.end(g); ++q) {
        const double d2 = (x[*q] - x[p]).squaredNorm();
        if (*q != p && d2 <= best) best = d2, found = true;
      }
    });
    if (found) nearest.push_back(std::sqrt(best));
  }
  if (nearest.empty()) return search;
  std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
  return nearest[nearest.size() / 2];
}

template <int D>
PrincipalDirections<D>::PrincipalDirections(const std::vector<Vec<D>>& cloud, double cell)
    : cloud_(cloud),
      radius_(std::min(kSpacings * median_spacing<D>(cloud, kMostCells * cell), kMostCells * cell)),
      groups_(cloud, 0, static_cast<long>(cloud.size()), Vec<D>::Zero(), radius_) {}

template <int D>
Vec<D> PrincipalDirections<D>::least_spread(long p) const {
  const Vec<D>& x = cloud_[p];
  WeightedMoments<D, true> moments;
  groups_.for_each_around(groups_.cell_of(x), [&](int g) {
    for (const long* q = groups_.begin(g); q != groups_.end(g); ++q) {
      const Vec<D> d = cloud_[*q] - x;  // about x: no cancellation far from the origin
      const double s = d.squaredNorm() / (radius_ * radius_);
      if (s >= 1.0) continue;
      moments.add(d, compact_weight(s));
    }
  });
  return least_spread_direction<D>(moments.matrix());
}

template class PrincipalDirections<2>;
template class PrincipalDirections<3>;
template double median_spacing<2>(const std::vector<Vec<2>>&, double);
template double median_spacing<3>(const std::vector<Vec<3>>&, double);

}  // namespace pellicle
