#include "pellicle/dist/window_carrier.hpp"

#include <numeric>

namespace pellicle {

namespace {

//! Index of node `n` of `grid`'s storage in the whole grid's (ghosts included, axis 0 fastest).
template <int D>
long whole_index(const Grid<D>& grid, long n) {
  const IVec<D> index = grid.unflatten(n);
  long flat = index[D - 1];
  for (int d = D - 2; d >= 0; --d)
    flat = flat * (grid.cells()[d] + 1 + 2 * Grid<D>::kGhost) + index[d];
  return flat;
}

}  // namespace

template <int D>
WindowCarrier<D>::WindowCarrier(const Grid<D>& before, const Grid<D>& after,
                                const Communicator* world)
    : world_(world) {
  for (int d = 0; d < D; ++d) whole_nodes_ *= before.cells()[d] + 1 + 2 * Grid<D>::kGhost;
  if (world)
    for (long n = 0; n < before.node_count(); ++n)
      from_.push_back(before.owns(n) ? whole_index(before, n) : -1);
  for (long n = 0; n < after.node_count(); ++n) to_.push_back(whole_index(after, n));
}

template <int D>
WindowCarrier<D>::WindowCarrier(const Grid<D>& before, const Communicator& world) : world_(&world) {
  for (int d = 0; d < D; ++d) whole_nodes_ *= before.cells()[d] + 1 + 2 * Grid<D>::kGhost;
  for (long n = 0; n < before.node_count(); ++n)
    from_.push_back(before.owns(n) ? whole_index(before, n) : -1);
  to_.resize(whole_nodes_);
  std::iota(to_.begin(), to_.end(), 0L);
}

template <int D>
void WindowCarrier<D>::carry(std::vector<double>& values) const {
  if (!world_) {  // from the whole grid: each node of the window reads its own value
    std::vector<double> window(to_.size(), 0.0);
    if (!values.empty())
      for (std::size_t n = 0; n < to_.size(); ++n) window[n] = values[to_[n]];
    values.swap(window);
    return;
  }
  if (values.empty()) values.assign(from_.size(), 0.0);
  std::vector<double> whole(whole_nodes_, 0.0);
  for (std::size_t n = 0; n < from_.size(); ++n)
    if (from_[n] >= 0) whole[from_[n]] = values[n];
  if (world_) world_->sum_in_rank_order(whole);  // one owner per node: exact
  values.resize(to_.size());
  for (std::size_t n = 0; n < to_.size(); ++n) values[n] = whole[to_[n]];
}

template class WindowCarrier<2>;
template class WindowCarrier<3>;

}  // namespace pellicle
