#include "pellicle/dist/decomposition.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace pellicle {

template <int D>
long CellCounts<D>::at(const IVec<D>& cell) const {
  long index = cell[D - 1];
  for (int d = D - 2; d >= 0; --d) index = index * cells[d] + cell[d];
  return points[index];
}

namespace {

//! Sums of the points of a box per plane across `axis` (weight 1 per cell when uniform).
template <int D>
std::vector<double> plane_sums(const CellCounts<D>& counts, const IVec<D>& lower,
                               const IVec<D>& upper, int axis, bool uniform) {
  std::vector<double> sums(upper[axis] - lower[axis], 0.0);
  IVec<D> cell = lower;
  while (true) {
    sums[cell[axis] - lower[axis]] += uniform ? 1.0 : static_cast<double>(counts.at(cell));
    int d = 0;  // next cell of the box, axis 0 fastest
    while (d < D && ++cell[d] == upper[d]) cell[d] = lower[d], ++d;
    if (d == D) break;
  }
  return sums;
}

template <int D>
void bisect(const CellCounts<D>& counts, const IVec<D>& lower, const IVec<D>& upper, int ranks,
            int first_rank, int min_cells, bool uniform, std::vector<Patch<D>>& out) {
  if (ranks == 1) {
    Patch<D> p{lower, upper, first_rank, 0};
    const auto sums = plane_sums(counts, lower, upper, 0, false);
    p.points = std::lround(std::accumulate(sums.begin(), sums.end(), 0.0));
    out.push_back(p);
    return;
  }
  const int low_ranks = ranks / 2;
  // Axes from the longest box extent down; the first with room for two patches is cut.
  std::array<int, D> axes;
  std::iota(axes.begin(), axes.end(), 0);
  std::stable_sort(axes.begin(), axes.end(),
                   [&](int a, int b) { return upper[a] - lower[a] > upper[b] - lower[b]; });
  for (int axis : axes) {
    const int extent = upper[axis] - lower[axis];
    if (extent < 2 * min_cells) continue;
    const auto sums = plane_sums(counts, lower, upper, axis, uniform);
    const double total = std::accumulate(sums.begin(), sums.end(), 0.0);
    const double target = total * low_ranks / ranks;
    double below = 0.0, best_error = std::numeric_limits<double>::infinity();
    // The best cuts' first run of neighbouring planes (empty planes between two bodies):
    // the middle one leaves the points farthest from the cut, so fewest cross it.
    int best_first = min_cells, best_last = min_cells;
    for (int c = 0; c < extent - min_cells; ++c) {
      below += sums[c];
      const int cut = c + 1;  // planes [0, cut) go to the lower side
      if (cut < min_cells) continue;
      const double error = std::abs(below - target);
      if (error < best_error)
        best_error = error, best_first = best_last = cut;
      else if (error == best_error && cut == best_last + 1)
        best_last = cut;
    }
    const int best = (best_first + best_last) / 2;
    IVec<D> middle_upper = upper, middle_lower = lower;
    middle_upper[axis] = lower[axis] + best;
    middle_lower[axis] = lower[axis] + best;
    bisect(counts, lower, middle_upper, low_ranks, first_rank, min_cells, uniform, out);
    bisect(counts, middle_lower, upper, ranks - low_ranks, first_rank + low_ranks, min_cells,
           uniform, out);
    return;
  }
  std::string size;
  for (int d = 0; d < D; ++d) size += (d ? " x " : "") + std::to_string(upper[d] - lower[d]);
  throw std::invalid_argument("cannot split " + size + " cells among " + std::to_string(ranks) +
                              " ranks with patches at least " + std::to_string(min_cells) +
                              " cells wide: use fewer ranks or a finer grid");
}

}  // namespace

template <int D>
std::vector<Patch<D>> bisect_patches(const CellCounts<D>& counts, int ranks, int min_cells) {
  if (ranks < 1) throw std::invalid_argument("the number of ranks must be at least 1");
  long cells = 1;
  for (int d = 0; d < D; ++d) cells *= counts.cells[d];
  if (static_cast<long>(counts.points.size()) != cells)
    throw std::invalid_argument("cell counts do not match the grid's cells");
  const bool uniform =
      std::all_of(counts.points.begin(), counts.points.end(), [](long n) { return n == 0; });
  std::vector<Patch<D>> patches;
  bisect(counts, IVec<D>::Zero().eval(), counts.cells, ranks, 0, std::max(min_cells, 1), uniform,
         patches);
  return patches;
}

template <int D>
double imbalance(const std::vector<Patch<D>>& patches) {
  long total = 0, most = 0;
  for (const auto& p : patches) total += p.points, most = std::max(most, p.points);
  if (total == 0) return 0.0;
  return static_cast<double>(most) * patches.size() / total - 1.0;
}

template struct CellCounts<2>;
template struct CellCounts<3>;
template std::vector<Patch<2>> bisect_patches<2>(const CellCounts<2>&, int, int);
template std::vector<Patch<3>> bisect_patches<3>(const CellCounts<3>&, int, int);
template double imbalance<2>(const std::vector<Patch<2>>&);
template double imbalance<3>(const std::vector<Patch<3>>&);

}  // namespace pellicle
