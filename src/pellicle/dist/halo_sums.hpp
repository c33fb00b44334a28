#pragma once
//! Completing the node sums of a distributed run (DESIGN.md, "Distributed runs"). After a
//! scatter each rank holds, at the nodes its points reach, only its own points' share; the
//! ranks that share a node add all shares in rank order (rank_order_sums.hpp), so every rank
//! updates its whole window as one process would. One exchange per scatter.

#include <vector>

#include "pellicle/dist/halo_plan.hpp"
#include "pellicle/dist/rank_order_sums.hpp"
#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/step_hook.hpp"

namespace pellicle {

template <int D>
class HaloSums {
 public:
  //! `plan`: the nodes shared with each other rank (halo_plan.hpp); `window`: the rank's grid
  //! (Grid::window of its patch's touched nodes).
  HaloSums(const Communicator& world, const std::vector<SharedWith>& plan, const Grid<D>& window);

  //! Complete the sums of the fields just scattered onto `grid` (a copy of the window).
  void complete(Grid<D>& grid, ScatteredFields fields);
  //! Complete the sums of node arrays of the window.
  void complete(const std::vector<NodeArray>& arrays);
  //! Doubles this rank sent in the last complete().
  long last_doubles_sent() const { return sums_.last_doubles_sent(); }

 private:
  RankOrderSums sums_;
  std::vector<RankOrderSums::Array> arrays_;
  std::vector<long> shared_;  //!< the nodes shared with any neighbour, as storage indices
};

extern template class HaloSums<2>;
extern template class HaloSums<3>;

}  // namespace pellicle
