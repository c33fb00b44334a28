#pragma once
//! Patch decomposition for distributed runs (DESIGN.md, "Distributed runs"): the grid's cells
//! are split into rectangular patches, one per rank, by recursive bisection of the point
//! count. Pure geometry (no MPI): every rank computes the same patches from the same counts.

#include <functional>
#include <string>
#include <vector>

#include "pellicle/core/types.hpp"

namespace pellicle {

//! Points per grid cell, cells[0] × … × cells[D−1] of them, axis 0 fastest.
template <int D>
struct CellCounts {
  IVec<D> cells;
  std::vector<long> points;
  long at(const IVec<D>& cell) const;
};

//! Cells [lower, upper) per axis, owned by `rank`.
template <int D>
struct Patch {
  IVec<D> lower, upper;
  int rank = 0;
  long points = 0;
  bool contains(const IVec<D>& cell) const {
    return (cell.array() >= lower.array()).all() && (cell.array() < upper.array()).all();
  }
};

//! The points a split weighs: for_each(visit) calls visit(cell, points) for cells holding
//! points (a cell may come more than once; its points add up).
template <int D>
using CellVisits = std::function<void(const std::function<void(const IVec<D>&, long)>& visit)>;

//! Adds each entry over the ranks whose points a split weighs together (nothing to do when
//! one rank visits all of them).
using SumOverRanks = std::function<void(std::vector<long>& values)>;

//! Split the grid's `cells` into `ranks` patches: a box of r ranks is cut across its longest
//! axis (in cells) at the plane whose share of the box's points is closest to ⌊r/2⌋/r (the
//! middle one of neighbouring planes that share it equally, as in a gap between bodies), and
//! each side gets ⌊r/2⌋ and ⌈r/2⌉ ranks, until every box has one rank. Every patch is at least
//! `min_cells` cells wide along every axis it was cut across, so a halo as wide as the kernel
//! only ever reaches adjacent patches. With no points at all, cells weigh equally. Patches
//! are numbered by rank, lower side first. Throws std::invalid_argument (naming the grid and
//! the rank count) when the grid is too small for that many patches.
//! The boxes of each level of the bisection are cut together: one visit of the points
//! gives every box's points per plane across its cut axis, `sum` adds them over the ranks.
//! So a split holds one count per plane of a level's boxes, not one per cell, and takes
//! ⌈log₂ ranks⌉ visits (one when `ranks` is 1).
template <int D>
std::vector<Patch<D>> bisect_patches(const IVec<D>& cells, int ranks, int min_cells,
                                     const CellVisits<D>& points, const SumOverRanks& sum);

//! The same from points per cell.
template <int D>
std::vector<Patch<D>> bisect_patches(const CellCounts<D>& counts, int ranks, int min_cells);

//! Which saved parts of a body a process reads when it continues a checkpoint:
//! read(piece, lower, upper) for rank `piece`'s piece of a distributed run's checkpoint, whose
//! points of the body lie within [lower, upper] (the whole space when the checkpoint's index
//! holds no boxes), or piece −1 for a checkpoint of one file. True: read it. An empty filter reads
//! every part (io/checkpoint.hpp).
template <int D>
using PartFilter = std::function<bool(long piece, const Vec<D>& lower, const Vec<D>& upper)>;

//! max / mean of the patches' point counts, minus 1: 0 is perfect balance; a run rebalances
//! when this exceeds its limit.
template <int D>
double imbalance(const std::vector<Patch<D>>& patches);

}  // namespace pellicle
