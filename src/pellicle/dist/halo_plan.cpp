#include "pellicle/dist/halo_plan.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pellicle {

template <int D>
IndexBox<D> touched_nodes(const Patch<D>& p, const IVec<D>& cells, int ghost, int reach) {
  IndexBox<D> box;
  for (int d = 0; d < D; ++d) {
    box.first[d] = std::max(p.lower[d] - reach, -ghost);
    box.last[d] = std::min(p.upper[d] + reach, cells[d] + ghost);
  }
  return box;
}

template <int D>
IndexBox<D> owned_nodes(const Patch<D>& p, const IVec<D>& cells, int ghost) {
  IndexBox<D> box;
  for (int d = 0; d < D; ++d) {
    box.first[d] = p.lower[d] == 0 ? -ghost : p.lower[d];
    box.last[d] = p.upper[d] == cells[d] ? cells[d] + ghost : p.upper[d] - 1;
  }
  return box;
}

namespace {

//! Flat indices of a box of indices, ascending (axis 0 fastest): index c along axis d is
//! stored at c + offset, with `extent` entries along it.
template <int D>
std::vector<long> flat_indices(const IndexBox<D>& box, const IVec<D>& extent, int offset) {
  std::vector<long> out;
  if (box.empty()) return out;
  IVec<D> c = box.first;
  while (true) {
    long index = c[D - 1] + offset;
    for (int d = D - 2; d >= 0; --d) index = index * extent[d] + c[d] + offset;
    out.push_back(index);
    int d = 0;
    while (d < D && ++c[d] > box.last[d]) c[d] = box.first[d], ++d;
    if (d == D) break;
  }
  return out;
}

}  // namespace

template <int D>
std::vector<long> node_indices(const IndexBox<D>& box, const IVec<D>& cells, int ghost) {
  return flat_indices<D>(box, (cells.array() + 1 + 2 * ghost).matrix(), ghost);
}

template <int D>
IndexBox<D> held_cells(const Patch<D>& p, const IVec<D>& cells, int reach) {
  IndexBox<D> box;
  for (int d = 0; d < D; ++d) {
    box.first[d] = std::max(p.lower[d] - reach - 1, 0);
    box.last[d] = std::min(p.upper[d] + reach, cells[d] - 1);
  }
  return box;
}

template <int D>
std::vector<long> cell_indices(const IndexBox<D>& box, const IVec<D>& cells) {
  return flat_indices(box, cells, 0);
}

namespace {

template <int D>
IndexBox<D> intersection(const IndexBox<D>& a, const IndexBox<D>& b) {
  return {a.first.cwiseMax(b.first), a.last.cwiseMin(b.last)};
}

//! What patch `rank` shares with each other patch: the entries of the intersection of its box
//! with theirs, lowest rank first.
template <int D, class Box, class Indices>
std::vector<SharedWith> shared_entries(const std::vector<Patch<D>>& patches, int rank, Box box,
                                       Indices indices) {
  if (rank < 0 || rank >= static_cast<int>(patches.size()))
    throw std::invalid_argument("no patch for rank " + std::to_string(rank));
  const IndexBox<D> mine = box(patches[rank]);
  std::vector<SharedWith> plan;
  for (int s = 0; s < static_cast<int>(patches.size()); ++s) {
    if (s == rank) continue;
    const IndexBox<D> both = intersection(mine, box(patches[s]));
    if (!both.empty()) plan.push_back({s, indices(both)});
  }
  return plan;
}

}  // namespace

template <int D>
std::vector<SharedWith> halo_plan(const std::vector<Patch<D>>& patches, const IVec<D>& cells,
                                  int ghost, int reach, int rank) {
  return shared_entries<D>(
      patches, rank, [&](const Patch<D>& p) { return touched_nodes(p, cells, ghost, reach); },
      [&](const IndexBox<D>& b) { return node_indices(b, cells, ghost); });
}

template <int D>
std::vector<SharedWith> shared_cells(const std::vector<Patch<D>>& patches, const IVec<D>& cells,
                                     int reach, int rank) {
  return shared_entries<D>(
      patches, rank, [&](const Patch<D>& p) { return held_cells(p, cells, reach); },
      [&](const IndexBox<D>& b) { return cell_indices(b, cells); });
}

template std::vector<SharedWith> halo_plan<2>(const std::vector<Patch<2>>&, const IVec<2>&, int,
                                              int, int);
template std::vector<SharedWith> halo_plan<3>(const std::vector<Patch<3>>&, const IVec<3>&, int,
                                              int, int);
template std::vector<SharedWith> shared_cells<2>(const std::vector<Patch<2>>&, const IVec<2>&, int,
                                                 int);
template std::vector<SharedWith> shared_cells<3>(const std::vector<Patch<3>>&, const IVec<3>&, int,
                                                 int);
template IndexBox<2> owned_nodes<2>(const Patch<2>&, const IVec<2>&, int);
template IndexBox<3> owned_nodes<3>(const Patch<3>&, const IVec<3>&, int);
template IndexBox<2> held_cells<2>(const Patch<2>&, const IVec<2>&, int);
template IndexBox<3> held_cells<3>(const Patch<3>&, const IVec<3>&, int);
template std::vector<long> cell_indices<2>(const IndexBox<2>&, const IVec<2>&);
template std::vector<long> cell_indices<3>(const IndexBox<3>&, const IVec<3>&);
template IndexBox<2> touched_nodes<2>(const Patch<2>&, const IVec<2>&, int, int);
template IndexBox<3> touched_nodes<3>(const Patch<3>&, const IVec<3>&, int, int);
template std::vector<long> node_indices<2>(const IndexBox<2>&, const IVec<2>&, int);
template std::vector<long> node_indices<3>(const IndexBox<3>&, const IVec<3>&, int);

}  // namespace pellicle
