#include "pellicle/dist/halo_sums.hpp"

#include <algorithm>

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

//! The node arrays a scatter wrote, as doubles per node.
template <int D>
struct NodeArrays {
  std::vector<std::pair<double*, int>> arrays;
  int per_node = 0;
  NodeArrays(Grid<D>& grid, ScatteredFields fields) {
    if (fields.mass) arrays.push_back({grid.mass.data(), 1});
    if (fields.momentum) arrays.push_back({grid.momentum.data()->data(), D});
    if (fields.force) arrays.push_back({grid.force.data()->data(), D});
    for (const auto& a : arrays) per_node += a.second;
  }
  void pack(const std::vector<long>& nodes, std::vector<double>& out) const {
    out.resize(nodes.size() * per_node);
    double* o = out.data();
    for (long n : nodes)
      for (const auto& [data, c] : arrays)
        for (int i = 0; i < c; ++i) *o++ = data[n * c + i];
  }
  void add(const std::vector<long>& nodes, const std::vector<double>& in) const {
    const double* v = in.data();
    for (long n : nodes)
      for (const auto& [data, c] : arrays)
        for (int i = 0; i < c; ++i) data[n * c + i] += *v++;
  }
  void clear(const std::vector<long>& nodes) const {
    for (long n : nodes)
      for (const auto& [data, c] : arrays)
        for (int i = 0; i < c; ++i) data[n * c + i] = 0.0;
  }
};

}  // namespace

template <int D>
HaloSums<D>::HaloSums(const Communicator& world, const std::vector<NodesSharedWith>& plan,
                      const Grid<D>& window)
    : world_(world), rank_(world.rank()) {
  for (const auto& e : plan) {
    Neighbour n{e.rank, {}};
    for (long g : e.nodes) n.nodes.push_back(storage_index(window, g));
    shared_.insert(shared_.end(), n.nodes.begin(), n.nodes.end());
    neighbours_.push_back(std::move(n));
  }
  std::sort(shared_.begin(), shared_.end());
  shared_.erase(std::unique(shared_.begin(), shared_.end()), shared_.end());
  outgoing_.resize(neighbours_.size());
  incoming_.resize(neighbours_.size());
}

template <int D>
void HaloSums<D>::complete(Grid<D>& grid, ScatteredFields fields) {
  const NodeArrays<D> arrays(grid, fields);
  last_sent_ = 0;
  for (std::size_t k = 0; k < neighbours_.size(); ++k) {
    outgoing_[k].rank = incoming_[k].rank = neighbours_[k].rank;
    arrays.pack(neighbours_[k].nodes, outgoing_[k].values);
    incoming_[k].values.resize(outgoing_[k].values.size());
    last_sent_ += static_cast<long>(outgoing_[k].values.size());
  }
  world_.exchange(outgoing_, incoming_);
  // Every shared node's sum in rank order over the ranks that hold it (0 + a = a exactly):
  // the lower ranks' shares, this rank's, the higher ranks'.
  arrays.pack(shared_, own_);
  arrays.clear(shared_);
  std::size_t k = 0;
  for (; k < neighbours_.size() && neighbours_[k].rank < rank_; ++k)
    arrays.add(neighbours_[k].nodes, incoming_[k].values);
  arrays.add(shared_, own_);
  for (; k < neighbours_.size(); ++k) arrays.add(neighbours_[k].nodes, incoming_[k].values);
}

template class HaloSums<2>;
template class HaloSums<3>;

}  // namespace pellicle
