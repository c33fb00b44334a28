#pragma once
//! Grid nodes inside a box take a prescribed velocity until a given time: a clamp (zero
//! velocity), the moving grip of a test machine, a piston. The points between such nodes
//! move with them; after `until` the nodes are free again (a released hold).
//!
//! Case keys (table [[boundary]], model = "prescribed-velocity"):
//!   lower, upper  m    corners of the box (D numbers each); nodes on its faces count
//!   velocity      m/s  the nodes' velocity (D numbers)
//!   until         s    time after which the nodes are free, default: never

#include <limits>
#include <memory>
#include <vector>

#include "pellicle/core/parameters.hpp"
#include "pellicle/core/types.hpp"
#include "pellicle/mpm/step_hook.hpp"

namespace pellicle {

template <int D>
class PrescribedVelocity final : public StepHook<D> {
 public:
  PrescribedVelocity(const Vec<D>& lower, const Vec<D>& upper, const Vec<D>& velocity,
                     double until = std::numeric_limits<double>::infinity())
      : lower_(lower), upper_(upper), velocity_(velocity), until_(until) {}

  void after_to_grid(Simulation<D>& simulation) override;
  void grid_replaced(const NodeCarrier&) override { nodes_.clear(); }

 private:
  Vec<D> lower_, upper_, velocity_;
  double until_;
  std::vector<std::pair<long, Vec<D>>> nodes_;  //!< found on the first step
};

template <int D>
std::unique_ptr<StepHook<D>> make_prescribed_velocity(ParameterReader& parameters);

extern template class PrescribedVelocity<2>;
extern template class PrescribedVelocity<3>;

}  // namespace pellicle
