#pragma once
//! The two steps of point management (management.hpp), each in its own file: merging
//! points closer than r_min h (§3.5, point_merging.cpp) and filling holes (§3.4,
//! hole_filling.cpp).

#include "pellicle/surface/management.hpp"

namespace pellicle {

//! §3.5: repeated rounds of merging the closest pairs until no pair is closer than r_min h.
template <int D>
void merge_close_points(PointCloud<D>& cloud, NeighbourSearch<D>& search,
                        const ManagementOptions& options, double weight_exponent,
                        ManagementReport& report);

//! §3.4: passes of adding points at the circumcentres of large one-ring triangles (and
//! between distant boundary points), each pass looking at the points the previous one added.
template <int D>
void fill_holes(PointCloud<D>& cloud, NeighbourSearch<D>& search, const ManagementOptions& options,
                double weight_exponent, ManagementReport& report);

}  // namespace pellicle
