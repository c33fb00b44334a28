#pragma once
//! Completing the node sums of a distributed run (DESIGN.md, "Distributed runs"). After a
//! scatter each rank holds, at the nodes its points reach, only its own points' share. The
//! ranks that share a node send each other their shares, and each adds all of them in rank
//! order: every copy of the node then holds the same sum, bit for bit, and every rank updates
//! its whole window as one process would. One exchange per scatter.

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
  HaloSums(const Communicator& world, const std::vector<NodesSharedWith>& plan,
           const Grid<D>& window);

  //! Complete the sums of the fields just scattered onto `grid` (a copy of the window).
  void complete(Grid<D>& grid, ScatteredFields fields);
  //! Doubles this rank sent in the last complete().
  long last_doubles_sent() const { return last_sent_; }

 private:
  struct Neighbour {
    int rank;
    std::vector<long> nodes;  //!< window storage indices of the nodes shared with it
  };
  const Communicator& world_;
  int rank_;
  std::vector<Neighbour> neighbours_;  //!< lowest rank first
  std::vector<long> shared_;           //!< every shared node once
  std::vector<double> own_;            //!< this rank's shares of them
  std::vector<Communicator::Message> outgoing_, incoming_;
  long last_sent_ = 0;
};

extern template class HaloSums<2>;
extern template class HaloSums<3>;

}  // namespace pellicle
