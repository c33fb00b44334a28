#pragma once
//! Point migration of a distributed run (DESIGN.md, "Distributed runs"): at the end of a step
//! the points whose cell has left the rank's patch go to the rank that owns that cell, with
//! every column, the declared ones included. Each body stays contiguous: its kept points (a
//! few of them moved to fill the leavers' places), then the arrivals in the senders' rank
//! order.

#include <vector>

#include "pellicle/dist/communicator.hpp"
#include "pellicle/mpm/particles.hpp"

namespace pellicle {

//! A point that leaves this rank, and the rank it goes to.
struct LeavingPoint {
  long point;
  int rank;
};

//! Send the `leaving` points (in ascending point order) to their ranks, and take in the points
//! the other ranks send here. Collective. Returns the number of points this rank sent.
//! `neighbours` (symmetric; null: any rank): the ranks points mostly go to, so that the
//! counts go only between them (Communicator::neighbour_all_to_all).
template <int D>
long migrate_points(const Communicator& world, const std::vector<LeavingPoint>& leaving,
                    Particles<D>& points, const std::vector<int>* neighbours = nullptr);

extern template long migrate_points<2>(const Communicator&, const std::vector<LeavingPoint>&,
                                       Particles<2>&, const std::vector<int>*);
extern template long migrate_points<3>(const Communicator&, const std::vector<LeavingPoint>&,
                                       Particles<3>&, const std::vector<int>*);

}  // namespace pellicle
