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

//! A box of the bisection: cells [lower, upper) for ranks [first_rank, first_rank + ranks).
//! A box of several ranks is cut across `axis`: cells below `cut` along it go to its lower
//! child, boxes[child], the rest to the upper one, boxes[child + 1].
template <int D>
struct Box {
  IVec<D> lower, upper;
  int ranks = 1, first_rank = 0;
  int axis = 0, cut = 0;
  int child = -1;       //!< −1 until cut
  bool pending = true;  //!< its points are still to be counted
  long offset = 0;      //!< where its plane sums start in its level's sums
  int planes() const { return ranks > 1 ? upper[axis] - lower[axis] : 1; }
};

//! The box of `boxes` (a bisection tree, rooted at boxes[0]) not yet cut that holds `cell`.
template <int D>
int box_of(const std::vector<Box<D>>& boxes, const IVec<D>& cell) {
  int b = 0;
  while (boxes[b].child >= 0) b = boxes[b].child + (cell[boxes[b].axis] >= boxes[b].cut ? 1 : 0);
  return b;
}

//! The axis a box of several ranks is cut across: from the longest extent down, the first
//! with room for two patches.
template <int D>
int cut_axis(const Box<D>& box, int min_cells) {
  std::array<int, D> axes;
  std::iota(axes.begin(), axes.end(), 0);
  const IVec<D> extent = box.upper - box.lower;
  std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return extent[a] > extent[b]; });
  for (int axis : axes)
    if (extent[axis] >= 2 * min_cells) return axis;
  std::string size;
  for (int d = 0; d < D; ++d) size += (d ? " x " : "") + std::to_string(extent[d]);
  throw std::invalid_argument("cannot split " + size + " cells among " + std::to_string(box.ranks) +
                              " ranks with patches at least " + std::to_string(min_cells) +
                              " cells wide: use fewer ranks or a finer grid");
}

//! The planes [0, cut) of a box that go to its lower side: the share of the points per plane
//! `sums` closest to low_ranks / ranks, with at least `min_cells` planes on either side; of
//! the best cuts' first run of neighbouring planes (empty planes between two bodies), the
//! middle one, which leaves the points farthest from the cut, so that fewest cross it.
int best_cut(const std::vector<double>& sums, int low_ranks, int ranks, int min_cells) {
  const int extent = static_cast<int>(sums.size());
  const double total = std::accumulate(sums.begin(), sums.end(), 0.0);
  const double target = total * low_ranks / ranks;
  double below = 0.0, best_error = std::numeric_limits<double>::infinity();
  int best_first = min_cells, best_last = min_cells;
  for (int c = 0; c < extent - min_cells; ++c) {
    below += sums[c];
    const int cut = c + 1;
    if (cut < min_cells) continue;
    const double error = std::abs(below - target);
    if (error < best_error)
      best_error = error, best_first = best_last = cut;
    else if (error == best_error && cut == best_last + 1)
      best_last = cut;
  }
  return (best_first + best_last) / 2;
}

}  // namespace

template <int D>
std::vector<Patch<D>> bisect_patches(const IVec<D>& cells, int ranks, int min_cells,
                                     const CellVisits<D>& points, const SumOverRanks& sum) {
  if (ranks < 1) throw std::invalid_argument("the number of ranks must be at least 1");
  min_cells = std::max(min_cells, 1);
  std::vector<Box<D>> boxes{{IVec<D>::Zero(), cells, ranks, 0}};
  std::vector<Patch<D>> patches;
  std::vector<int> level = {0};  // the boxes to count and cut
  bool uniform = false;          // no points at all: cells weigh equally
  for (bool root = true; !level.empty(); root = false) {
    long planes = 0;
    for (int b : level) {
      if (boxes[b].ranks > 1) boxes[b].axis = cut_axis(boxes[b], min_cells);
      boxes[b].offset = planes;
      planes += boxes[b].planes();
    }
    std::vector<long> counts(planes, 0);
    if (!uniform) {
      points([&](const IVec<D>& cell, long n) {
        const Box<D>& box = boxes[box_of(boxes, cell)];
        if (box.pending)
          counts[box.offset + (box.ranks > 1 ? cell[box.axis] - box.lower[box.axis] : 0)] += n;
      });
      sum(counts);
      uniform = root && std::all_of(counts.begin(), counts.end(), [](long n) { return n == 0; });
    }
    std::vector<int> next;
    for (int b : level) {
      const Box<D> box = boxes[b];  // uncut and pending, as its sides start
      boxes[b].pending = false;
      if (box.ranks == 1) {  // the grid, one patch
        patches.push_back({box.lower, box.upper, box.first_rank, counts[box.offset]});
        continue;
      }
      std::vector<double> sums(box.planes());
      long cross_section = 1;  // cells per plane
      for (int d = 0; d < D; ++d)
        if (d != box.axis) cross_section *= box.upper[d] - box.lower[d];
      for (int c = 0; c < box.planes(); ++c)
        sums[c] = static_cast<double>(uniform ? cross_section : counts[box.offset + c]);
      const int low_ranks = box.ranks / 2;
      const int cut = best_cut(sums, low_ranks, box.ranks, min_cells);
      Box<D> lower = box, upper = box;
      lower.upper[box.axis] = upper.lower[box.axis] = box.lower[box.axis] + cut;
      lower.ranks = low_ranks;
      upper.ranks = box.ranks - low_ranks;
      upper.first_rank = box.first_rank + low_ranks;
      long lower_points = 0, upper_points = 0;  // for the sides of one rank: their patches
      for (int c = 0; c < box.planes(); ++c)
        (c < cut ? lower_points : upper_points) += counts[box.offset + c];
      boxes[b].cut = box.lower[box.axis] + cut;
      boxes[b].child = static_cast<int>(boxes.size());
      for (const auto& [side, points_in] :
           {std::pair{lower, lower_points}, std::pair{upper, upper_points}}) {
        if (side.ranks == 1) {
          patches.push_back({side.lower, side.upper, side.first_rank, points_in});
          boxes.push_back(side);
          boxes.back().pending = false;
        } else {
          next.push_back(static_cast<int>(boxes.size()));
          boxes.push_back(side);
        }
      }
    }
    level = std::move(next);
  }
  std::sort(patches.begin(), patches.end(),
            [](const Patch<D>& a, const Patch<D>& b) { return a.rank < b.rank; });
  return patches;
}

template <int D>
std::vector<Patch<D>> bisect_patches(const CellCounts<D>& counts, int ranks, int min_cells) {
  long cells = 1;
  for (int d = 0; d < D; ++d) cells *= counts.cells[d];
  if (static_cast<long>(counts.points.size()) != cells)
    throw std::invalid_argument("cell counts do not match the grid's cells");
  auto each_cell = [&](const std::function<void(const IVec<D>&, long)>& visit) {
    IVec<D> cell = IVec<D>::Zero();
    for (long n : counts.points) {
      if (n != 0) visit(cell, n);
      for (int d = 0; d < D && ++cell[d] == counts.cells[d]; ++d) cell[d] = 0;  // axis 0 fastest
    }
  };
  return bisect_patches<D>(counts.cells, ranks, min_cells, each_cell, [](std::vector<long>&) {});
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
template std::vector<Patch<2>> bisect_patches<2>(const IVec<2>&, int, int, const CellVisits<2>&,
                                                 const SumOverRanks&);
template std::vector<Patch<3>> bisect_patches<3>(const IVec<3>&, int, int, const CellVisits<3>&,
                                                 const SumOverRanks&);
template double imbalance<2>(const std::vector<Patch<2>>&);
template double imbalance<3>(const std::vector<Patch<3>>&);

}  // namespace pellicle
