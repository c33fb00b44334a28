#include "pellicle/dist/halo_plan.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pellicle {

template <int D>
NodeBox<D> touched_nodes(const Patch<D>& p, const IVec<D>& cells, int ghost, int reach) {
  NodeBox<D> box;
  for (int d = 0; d < D; ++d) {
    box.first[d] = std::max(p.lower[d] - reach, -ghost);
    box.last[d] = std::min(p.upper[d] + reach, cells[d] + ghost);
  }
  return box;
}

template <int D>
std::vector<long> node_indices(const NodeBox<D>& box, const IVec<D>& cells, int ghost) {
  std::vector<long> out;
  if (box.empty()) return out;
  IVec<D> c = box.first;
  while (true) {
    long index = c[D - 1] + ghost;
    for (int d = D - 2; d >= 0; --d) index = index * (cells[d] + 1 + 2 * ghost) + c[d] + ghost;
    out.push_back(index);
    int d = 0;
    while (d < D && ++c[d] > box.last[d]) c[d] = box.first[d], ++d;
    if (d == D) break;
  }
  return out;
}

namespace {

template <int D>
NodeBox<D> intersection(const NodeBox<D>& a, const NodeBox<D>& b) {
  return {a.first.cwiseMax(b.first), a.last.cwiseMin(b.last)};
}

}  // namespace

template <int D>
std::vector<NodesSharedWith> halo_plan(const std::vector<Patch<D>>& patches, const IVec<D>& cells,
                                       int ghost, int reach, int rank) {
  if (rank < 0 || rank >= static_cast<int>(patches.size()))
    throw std::invalid_argument("no patch for rank " + std::to_string(rank));
  const NodeBox<D> mine = touched_nodes(patches[rank], cells, ghost, reach);
  std::vector<NodesSharedWith> plan;
  for (int s = 0; s < static_cast<int>(patches.size()); ++s) {
    if (s == rank) continue;
    const NodeBox<D> both = intersection(mine, touched_nodes(patches[s], cells, ghost, reach));
    if (!both.empty()) plan.push_back({s, node_indices(both, cells, ghost)});
  }
  return plan;
}

template std::vector<NodesSharedWith> halo_plan<2>(const std::vector<Patch<2>>&, const IVec<2>&,
                                                   int, int, int);
template std::vector<NodesSharedWith> halo_plan<3>(const std::vector<Patch<3>>&, const IVec<3>&,
                                                   int, int, int);
template NodeBox<2> touched_nodes<2>(const Patch<2>&, const IVec<2>&, int, int);
template NodeBox<3> touched_nodes<3>(const Patch<3>&, const IVec<3>&, int, int);
template std::vector<long> node_indices<2>(const NodeBox<2>&, const IVec<2>&, int);
template std::vector<long> node_indices<3>(const NodeBox<3>&, const IVec<3>&, int);

}  // namespace pellicle
