#pragma once
//! Membrane points grouped by the grid cell that holds them: the local normal constructions
//! work cell by cell.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "pellicle/core/types.hpp"

namespace pellicle {

template <int D>
class CellGroups {
 public:
  //! Group points [begin, end) of `x` by cell of a grid with a node at `origin`, cell `h`.
  CellGroups(const std::vector<Vec<D>>& x, long begin, long end, const Vec<D>& origin, double h);

  int size() const { return static_cast<int>(cells_.size()); }
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

  static std::int64_t key(const IVec<D>& c) {
    std::int64_t k = 0;
    for (int d = 0; d < D; ++d) k = (k << 21) | static_cast<std::int64_t>(c[d] + (1 << 20));
    return k;
  }

 private:
  std::vector<long> order_;
  std::vector<long> starts_;
  std::vector<IVec<D>> cells_;
  std::unordered_map<std::int64_t, int> index_;
};

extern template class CellGroups<2>;
extern template class CellGroups<3>;

}  // namespace pellicle
