#pragma once
//! Cell grouping of points: the points of a set grouped by the cell of a regular grid that
//! holds them, and the occupied cells around a cell. The membranes' local normal constructions
//! (normals/) work cell by cell on the background grid; their neighbourhood walks (orientation,
//! principal directions) look up the points of the 3^D cells around a point. Unlike the k-d tree
//! of neighbour_search.hpp, it visits points cell by cell in a fixed order, the order those
//! constructions' sums are taken in.

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "pellicle/core/types.hpp"

namespace pellicle {

template <int D>
class CellGroups {
 public:
  //! Group points [begin, end) of `x` by cell of a grid with a node at `origin`, cell `h`.
  //! Throws std::invalid_argument for a point whose cell cannot be numbered (a coordinate not
  //! finite, or 2^30 cells or more from the origin).
  CellGroups(const std::vector<Vec<D>>& x, long begin, long end, const Vec<D>& origin, double h);

  int size() const { return static_cast<int>(cells_.size()); }
  //! The cell holding x (not checked: for places near the grouped points).
  IVec<D> cell_of(const Vec<D>& x) const {
    IVec<D> c;
    for (int d = 0; d < D; ++d) c[d] = static_cast<int>(std::floor((x[d] - origin_[d]) / h_));
    return c;
  }
  const IVec<D>& cell(int group) const { return cells_[group]; }
  //! Points of a group (absolute indices).
  const long* begin(int group) const { return order_.data() + starts_[group]; }
  const long* end(int group) const { return order_.data() + starts_[group + 1]; }
  long count(int group) const { return starts_[group + 1] - starts_[group]; }
  //! Group of a cell, or −1 when the cell holds no point.
  int find(const IVec<D>& cell) const {
    const auto it = index_.find(key(cell));
    return it == index_.end() ? -1 : it->second;
  }
  //! Number of points in the cell (0 if none).
  long count_in(const IVec<D>& cell) const {
    const int g = find(cell);
    return g < 0 ? 0 : count(g);
  }

  //! Call f(group) for every occupied cell of the 3^D around `cell`, itself included.
  template <class F>
  void for_each_around(const IVec<D>& cell, F&& f) const {
    for (int o = 0; o < (D == 2 ? 9 : 27); ++o) {
      IVec<D> near = cell;
      int rest = o;
      for (int d = 0; d < D; ++d) near[d] += rest % 3 - 1, rest /= 3;
      const int g = find(near);
      if (g >= 0) f(g);
    }
  }
  //! Call f(group) for every occupied cell of the block of s^D cells from `lower`.
  template <class F>
  void for_each_in_block(const IVec<D>& lower, int s, F&& f) const {
    for (int c = 0; c < static_cast<int>(std::pow(s, D)); ++c) {
      IVec<D> inner;
      int rest = c;
      for (int d = 0; d < D; ++d) inner[d] = lower[d] + rest % s, rest /= s;
      const int g = find(inner);
      if (g >= 0) f(g);
    }
  }

  static std::int64_t key(const IVec<D>& c) {
    std::int64_t k = 0;
    for (int d = 0; d < D; ++d) k = (k << 21) | static_cast<std::int64_t>(c[d] + (1 << 20));
    return k;
  }

 private:
  Vec<D> origin_;
  double h_;
  std::vector<long> order_;
  std::vector<long> starts_;
  std::vector<IVec<D>> cells_;
  std::unordered_map<std::int64_t, int> index_;
};

extern template class CellGroups<2>;
extern template class CellGroups<3>;

}  // namespace pellicle
