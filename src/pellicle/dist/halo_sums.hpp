#pragma once
//! Completing the node sums of a distributed run (DESIGN.md, "Distributed runs"). After a
//! scatter each rank holds, at the nodes its points reach, only its own points' share. The
//! halo nodes' shares go to their owners, who add them in rank order; the owners then send
//! the complete sums back to every rank whose halo holds the node. Every rank then has the
//! whole grid's sums on all of its window and updates it as one process would.

#include <vector>

#include "pellicle/dist/communicator.hpp"
#include "pellicle/dist/halo_plan.hpp"
#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/step_hook.hpp"

namespace pellicle {

template <int D>
class HaloSums {
 public:
  //! `window` is the rank's grid (Grid::window of its patch's touched nodes).
  HaloSums(const Communicator& world, const std::vector<HaloExchange>& plan, const Grid<D>& window);

  //! Complete the sums of the fields just scattered onto `grid` (a copy of the window).
  void complete(Grid<D>& grid, ScatteredFields fields);
  //! Doubles this rank sent in the last complete() (both passes).
  long last_doubles_sent() const { return last_sent_; }

 private:
  struct Neighbour {
    int rank;
    std::vector<long> halo;   //!< window storage indices of its nodes in this rank's halo
    std::vector<long> owned;  //!< window storage indices of this rank's nodes in its halo
  };
  const Communicator& world_;
  std::vector<Neighbour> neighbours_;
  std::vector<Communicator::Message> outgoing_, incoming_;
  long last_sent_ = 0;
};

extern template class HaloSums<2>;
extern template class HaloSums<3>;

}  // namespace pellicle
