#pragma once
//! Which grid nodes the ranks of a distributed run share (DESIGN.md, "Distributed runs").
//! Nodes are named by their global flat index on the whole grid with its ghost layers
//! (Grid::flatten), so the lists do not depend on how a rank stores its patch. The points of
//! a patch of cells [lower, upper) touch the nodes of [lower − reach, upper + reach] per axis
//! (within the grid's ghost layers), `reach` as wide as the kernel: its window. Two patches share
//! the nodes both windows hold; after a scatter each rank adds every sharing rank's share of them.
//! Pure geometry, the same on every rank.

#include <vector>

#include "pellicle/dist/decomposition.hpp"

namespace pellicle {

//! The nodes a rank shares with another rank, in ascending global index (the same list on
//! both sides).
struct NodesSharedWith {
  int rank = 0;
  std::vector<long> nodes;
};

//! The nodes patch `rank` shares with every other patch it shares any with, lowest rank first.
//! `cells` is the whole grid's cells per axis, `ghost` its ghost layers, `reach` the window's
//! layers beyond the patch. Throws std::invalid_argument when `rank` names no patch.
template <int D>
std::vector<NodesSharedWith> halo_plan(const std::vector<Patch<D>>& patches, const IVec<D>& cells,
                                       int ghost, int reach, int rank);

//! Nodes (per axis, in cell-corner coordinates from −ghost to cells + ghost): an inclusive box.
template <int D>
struct NodeBox {
  IVec<D> first, last;
  bool empty() const { return ((last - first).array() < 0).any(); }
};
//! The nodes the points of patch p touch: its window.
template <int D>
NodeBox<D> touched_nodes(const Patch<D>& p, const IVec<D>& cells, int ghost, int reach);
//! Global flat indices of the nodes of a box, ascending (axis 0 fastest, as Grid::flatten).
template <int D>
std::vector<long> node_indices(const NodeBox<D>& box, const IVec<D>& cells, int ghost);

}  // namespace pellicle
