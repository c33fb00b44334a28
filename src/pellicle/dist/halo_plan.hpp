#pragma once
//! Which grid nodes and cells the ranks of a distributed run share (DESIGN.md, "Distributed runs").
//! Nodes are named by their global flat index on the whole grid with its ghost layers
//! (Grid::flatten), so the lists do not depend on how a rank stores its patch. The points of
//! a patch of cells [lower, upper) touch the nodes of [lower − reach, upper + reach] per axis
//! (within the grid's ghost layers), `reach` as wide as the kernel: its window. Two patches share
//! the nodes both windows hold; after a scatter each rank adds every sharing rank's share of them.
//! Pure geometry, the same on every rank.

#include <vector>

#include "pellicle/dist/decomposition.hpp"

namespace pellicle {

//! The entries (grid nodes or cells) a rank shares with another rank, in ascending global
//! index (the same list on both sides).
struct SharedWith {
  int rank = 0;
  std::vector<long> indices;
};

//! The nodes patch `rank` shares with every other patch it shares any with, lowest rank first.
//! `cells` is the whole grid's cells per axis, `ghost` its ghost layers, `reach` the window's
//! layers beyond the patch. Throws std::invalid_argument when `rank` names no patch.
template <int D>
std::vector<SharedWith> halo_plan(const std::vector<Patch<D>>& patches, const IVec<D>& cells,
                                  int ghost, int reach, int rank);

//! An inclusive box of indices per axis: nodes in cell-corner coordinates from −ghost to
//! cells + ghost, or cells from 0 to cells − 1.
template <int D>
struct IndexBox {
  IVec<D> first, last;
  bool empty() const { return ((last - first).array() < 0).any(); }
};
//! The nodes the points of patch p touch: its window.
template <int D>
IndexBox<D> touched_nodes(const Patch<D>& p, const IVec<D>& cells, int ghost, int reach);
//! The nodes patch p owns: those of its cells' lower corners, and at the grid's sides the
//! nodes up to the outer ghost layer. Every node of the grid is owned by one patch.
template <int D>
IndexBox<D> owned_nodes(const Patch<D>& p, const IVec<D>& cells, int ghost);
//! Global flat indices of the nodes of a box, ascending (axis 0 fastest, as Grid::flatten).
template <int D>
std::vector<long> node_indices(const IndexBox<D>& box, const IVec<D>& cells, int ghost);

//! The cells whose cell-field values (contact's colour functions, cell densities;
//! mpm/cell_field.hpp) patch p holds: those its points spread to with the quadratic B-spline
//! on cell centres, one cell beyond a point's own (and a point moves less than a cell in a
//! step before it migrates), and those on either side of its window's nodes, whose
//! gradients read them: cells [lower − reach − 1, upper + reach] within the grid.
template <int D>
IndexBox<D> held_cells(const Patch<D>& p, const IVec<D>& cells, int reach);
//! Flat indices of the cells of a box, ascending (axis 0 fastest, as cell_field.hpp).
template <int D>
std::vector<long> cell_indices(const IndexBox<D>& box, const IVec<D>& cells);
//! The cells patch `rank` shares with every other patch it shares any with, lowest rank first.
template <int D>
std::vector<SharedWith> shared_cells(const std::vector<Patch<D>>& patches, const IVec<D>& cells,
                                     int reach, int rank);

}  // namespace pellicle
