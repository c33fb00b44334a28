#include "pellicle/dist/halo_sums.hpp"

namespace pellicle {

namespace {

//! The window storage index of a node given by its global flat index (halo_plan.hpp).
template <int D>
long storage_index(const Grid<D>& window, long global) {
  IVec<D> index;
  for (int d = 0; d < D; ++d) {
    const long n = window.cells()[d] + 1 + 2 * Grid<D>::kGhost;
    index[d] = static_cast<int>(global % n);
    global /= n;
  }
  return window.flatten(index);
}

//! The shared nodes as window storage indices.
template <int D>
std::vector<RankOrderSums::Neighbour> in_window(const std::vector<SharedWith>& plan,
                                                const Grid<D>& window) {
  std::vector<RankOrderSums::Neighbour> neighbours;
  for (const auto& e : plan) {
    RankOrderSums::Neighbour n{e.rank, {}};
    for (long g : e.indices) n.entries.push_back(storage_index(window, g));
    neighbours.push_back(std::move(n));
  }
  return neighbours;
}

}  // namespace

template <int D>
HaloSums<D>::HaloSums(const Communicator& world, const std::vector<SharedWith>& plan,
                      const Grid<D>& window)
    : sums_(world, in_window(plan, window)) {
  for (const auto& e : plan)
    for (long g : e.indices) shared_.push_back(storage_index(window, g));
}

template <int D>
void HaloSums<D>::complete(Grid<D>& grid, ScatteredFields fields) {
  // The neighbours' shares may land where this rank's points did not reach.
  grid.mark_live(shared_.data(), shared_.data() + shared_.size());
  arrays_.clear();
  if (fields.mass) arrays_.push_back({grid.mass.data(), 1});
  if (fields.momentum) arrays_.push_back({grid.momentum.data()->data(), D});
  if (fields.force) arrays_.push_back({grid.force.data()->data(), D});
  sums_.complete(arrays_);
}

template <int D>
void HaloSums<D>::complete(const std::vector<NodeArray>& arrays) {
  arrays_.clear();
  for (const auto& a : arrays) arrays_.push_back({a.data, a.components});
  sums_.complete(arrays_);
}

template class HaloSums<2>;
template class HaloSums<3>;

}  // namespace pellicle
