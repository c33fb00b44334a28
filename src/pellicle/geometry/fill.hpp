#pragma once
//! Fill a region with material points: every grid cell is split into n sub-cells per
//! direction and a point is put at each sub-cell centre that lies inside the region (the
//! seeds' "points per cell", thesis appendix A.4 `nprg`). Each point stands for the volume of
//! its sub-cell.

#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/geometry/region.hpp"

namespace pellicle {

//! Sub-cell centres inside `region` within the grid box [lower, upper] of cell size h, in
//! cell-major order (cells row by row, then the sub-cells of each cell).
template <int D>
std::vector<Vec<D>> fill_region(const Region<D>& region, const Vec<D>& lower, const Vec<D>& upper,
                                double h, int points_per_direction);

}  // namespace pellicle
