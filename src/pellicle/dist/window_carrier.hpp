#pragma once
//! Per-node values a hook keeps (contact-release's node states), carried from a rank's grid
//! storage to another: to its new window when the patches are split anew
//! (StepHook::grid_replaced), or to the whole grid for a checkpoint. Each node takes the value
//! the rank that owned it held (Grid::owns): the owners put their values into one sum over
//! the ranks of the whole grid's nodes, exact with one owner per node.

#include <vector>

#include "pellicle/dist/communicator.hpp"
#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/step_hook.hpp"

namespace pellicle {

template <int D>
class WindowCarrier final : public NodeCarrier {
 public:
  //! From `before` to the window `after`. With `world` null `before` is the whole grid, the
  //! same on every rank, and each node of the window reads its own value (no exchange).
  WindowCarrier(const Grid<D>& before, const Grid<D>& after, const Communicator* world);
  //! From `before` to the whole grid, in its own storage order.
  WindowCarrier(const Grid<D>& before, const Communicator& world);

  void carry(std::vector<double>& values) const override;

 private:
  const Communicator* world_;
  long whole_nodes_ = 1;
  //! Whole-grid index of each node of `before` it owns, else −1; empty when `before` is the
  //! whole grid (world null), whose storage order is the whole grid's.
  std::vector<long> from_;
  std::vector<long> to_;  //!< whole-grid index of each node of `after`
};

extern template class WindowCarrier<2>;
extern template class WindowCarrier<3>;

}  // namespace pellicle
