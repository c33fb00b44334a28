#pragma once
//! Chambers and parts of a point cloud (Suchde & Kuhnert §3.6): every point carries a
//! chamber id, and its neighbourhood S_i holds only points of its own part (its chamber,
//! normals not facing its own: PointCloud::on_part); the other points within h are
//! S_i^ext, where contact is looked for. Chambers are relabelled by connected components,
//! so a surface that comes apart becomes two chambers.

#include <cstdint>
#include <vector>

#include "pellicle/pointcloud/neighbour_search.hpp"
#include "pellicle/surface/point_cloud.hpp"

namespace pellicle {

//! Split every neighbourhood of `lists` into the points on the point's own part (kept in
//! `lists`, in their order, the point itself first) and the others (moved to `external`,
//! when given, in their order; else dropped).
template <int D>
void split_by_part(const PointCloud<D>& cloud, NeighbourLists& lists, NeighbourLists* external);

struct ChamberReport {
  int split = 0;    //!< chambers that came apart
  long debris = 0;  //!< points removed in components smaller than the smallest part
  bool changed() const { return split > 0 || debris > 0; }
};

//! Give every point with fewer than `minimum` neighbours in its own part (the rim where a
//! contact cut a surface, the part's edge beside another part) its `minimum` nearest points
//! of that part within 2 h, as the search does for the whole cloud (the stencils widen their
//! weight to match). `search` must hold the cloud as it is now. Returns how many points have
//! fewer than `minimum` even so (a neck collapsed into a thread of points): no stencil fits
//! them.
template <int D>
long top_up_parts(const PointCloud<D>& cloud, const NeighbourSearch<D>& search,
                  NeighbourLists& lists, int minimum, std::vector<std::uint8_t>& short_of);

//! Relabel the chambers by connected components: two points of one chamber are connected
//! when one lies in the other's `own` or `external` list (within h of each other). A chamber
//! of several components keeps its id on the largest; the others take ids above every id in
//! use. Parts (points linked through `own` alone) of fewer than `smallest_part` points are
//! removed: debris that contact deletion leaves where a neck was cut, too few points for a
//! normal. The caller then finds the neighbours again.
template <int D>
ChamberReport split_chambers(PointCloud<D>& cloud, const NeighbourLists& own,
                             const NeighbourLists& external, long smallest_part = 0);

}  // namespace pellicle
