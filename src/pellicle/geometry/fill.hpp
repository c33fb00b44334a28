#pragma once
//! Fill a region with material points: every grid cell is split into n sub-cells per
//! direction and a point is put at each sub-cell centre that lies inside the region (the
//! seeds' "points per cell", thesis appendix A.4 `nprg`). Each point stands for the volume of
//! its sub-cell.

#include <algorithm>
#include <cmath>
#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/geometry/region.hpp"

namespace pellicle {

//! visit(x) for each sub-cell centre x inside `region` within the grid box [lower, upper] of
//! cell size h, in cell-major order (cells row by row, then the sub-cells of each cell): the
//! same points in the same order on every walk, none of them kept.
template <int D, class Visit>
void for_each_fill_point(const Region<D>& region, const Vec<D>& lower, const Vec<D>& upper,
                         double h, int points_per_direction, Visit&& visit) {
  const int n = points_per_direction;
  const Box<D> b = region.bounds();
  IVec<D> first, last;
  for (int d = 0; d < D; ++d) {
    const int cells = static_cast<int>(std::lround((upper[d] - lower[d]) / h));
    const double lo = std::max(b.lower[d], lower[d]), hi = std::min(b.upper[d], upper[d]);
    first[d] = std::clamp(static_cast<int>(std::floor((lo - lower[d]) / h)), 0, cells);
    last[d] = std::clamp(static_cast<int>(std::ceil((hi - lower[d]) / h)), 0, cells);
  }
  if ((first.array() >= last.array()).any()) return;
  const double sub = h / n;
  const int per_cell = static_cast<int>(std::pow(n, D));
  IVec<D> cell = first;
  while (true) {
    for (int k = 0; k < per_cell; ++k) {
      Vec<D> x;
      int rest = k;
      for (int d = 0; d < D; ++d) {
        x[d] = lower[d] + cell[d] * h + (rest % n + 0.5) * sub;
        rest /= n;
      }
      if (region.contains(x)) visit(x);
    }
    int d = 0;
    for (; d < D; ++d) {
      if (++cell[d] < last[d]) break;
      cell[d] = first[d];
    }
    if (d == D) break;
  }
}

//! The points of for_each_fill_point, in its order.
template <int D>
std::vector<Vec<D>> fill_region(const Region<D>& region, const Vec<D>& lower, const Vec<D>& upper,
                                double h, int points_per_direction);

}  // namespace pellicle
