#pragma once
//! Which grid nodes the ranks of a distributed run exchange (DESIGN.md, "Distributed runs").
//! Nodes are named by their global flat index on the whole grid with its ghost layers
//! (Grid::flatten), so the lists do not depend on how a rank stores its patch. A patch of
//! cells [lower, upper) owns the nodes [lower, upper) per axis, and also the nodes up to the
//! ghost layers where it reaches the domain's side; its points touch the nodes of
//! [lower − ghost, upper + ghost]. The nodes it touches but does not own are its halo:
//! after to_grid their sums go to their owners, after the grid update the owners' values come
//! back. Pure geometry, the same on every rank.

#include <vector>

#include "pellicle/dist/decomposition.hpp"

namespace pellicle {

//! One neighbour's share of a rank's halo exchange; both lists in ascending global index, so
//! what one rank sends lines up with what the other expects.
struct HaloExchange {
  int rank = 0;
  std::vector<long> to_owner;   //!< this rank's halo nodes that `rank` owns
  std::vector<long> from_halo;  //!< nodes this rank owns that are in `rank`'s halo
};

//! The exchanges of patch `rank` with every other patch it shares nodes with, lowest rank
//! first. `cells` is the whole grid's cells per axis, `ghost` its ghost layers (the kernel's
//! reach). Throws std::invalid_argument when `rank` names no patch.
template <int D>
std::vector<HaloExchange> halo_plan(const std::vector<Patch<D>>& patches, const IVec<D>& cells,
                                    int ghost, int rank);

//! Nodes (per axis, in cell-corner coordinates from −ghost to cells + ghost) that patch p
//! owns, and that its points touch: inclusive boxes.
template <int D>
struct NodeBox {
  IVec<D> first, last;
  bool empty() const { return ((last - first).array() < 0).any(); }
};
template <int D>
NodeBox<D> owned_nodes(const Patch<D>& p, const IVec<D>& cells, int ghost);
template <int D>
NodeBox<D> touched_nodes(const Patch<D>& p, const IVec<D>& cells, int ghost);
//! Global flat indices of the nodes of a box, ascending (axis 0 fastest, as Grid::flatten).
template <int D>
std::vector<long> node_indices(const NodeBox<D>& box, const IVec<D>& cells, int ghost);

}  // namespace pellicle
