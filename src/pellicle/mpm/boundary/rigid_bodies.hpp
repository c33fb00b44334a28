#pragma once
//! Rigid bodies as a boundary condition (step hook): every grid node a rigid body's points
//! touch takes the body's prescribed velocity in the grid solve, so the body acts on the
//! others as a moving wall of any shape; its points keep that velocity exactly (FLIP would
//! add the nodes' change). With per-body fields the centre-of-mass field takes every rigid
//! body's velocity and each body's own field only its own, so the others meet it through
//! the contact rule.

#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/mpm/step_hook.hpp"

namespace pellicle {

template <int D>
class RigidBodies final : public StepHook<D> {
 public:
  //! `bodies`: indices of the rigid bodies; `velocity`: each one's prescribed velocity.
  RigidBodies(std::vector<int> bodies, std::vector<Vec<D>> velocity)
      : bodies_(std::move(bodies)), velocity_(std::move(velocity)) {}

  void after_to_grid(Simulation<D>& simulation) override;
  void after_to_points(Simulation<D>& simulation) override;
  bool sets_point_velocities() const override { return true; }

 private:
  std::vector<int> bodies_;
  std::vector<Vec<D>> velocity_;
  std::vector<std::vector<long>> touched_;  //!< per rigid body, work array
  std::vector<double> marks_;  //!< distributed runs: per node and rigid body, work array
  std::vector<std::pair<long, Vec<D>>> prescribed_;  //!< work array
};

extern template class RigidBodies<2>;
extern template class RigidBodies<3>;

}  // namespace pellicle
