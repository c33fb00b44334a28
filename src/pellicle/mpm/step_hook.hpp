#pragma once
//! Hooks: what acts on the step at its named points without living in it — rigid bodies and
//! other boundary conditions (mpm/boundary/), contact models (mpm/contact/), and later halo
//! exchange. A new one is a class here plus its registration; step() does not change.

#include <string>

namespace pellicle {

template <int D>
class Simulation;
class CheckpointReader;
class CheckpointWriter;

//! Which grid velocities a hook sees after a grid update: the Lagrangian ones after the
//! momentum solve (they move the points), or the convected ones of the MUSL remap (they give
//! the strain rates).
enum class GridPass { lagrangian, convected };

template <int D>
class StepHook {
 public:
  virtual ~StepHook() = default;
  //! After `to_grid`: mass, momentum and forces are on the grid fields.
  virtual void after_to_grid(Simulation<D>&) {}
  //! After the grid velocities were updated (momentum solve, or the MUSL remap).
  virtual void after_grid_update(Simulation<D>&, GridPass, double /*dt*/) {}
  //! After `to_points`: points have their new positions and velocities.
  virtual void after_to_points(Simulation<D>&) {}
  //! The hook needs each body in its own grid field (contact models).
  virtual bool needs_body_fields() const { return false; }
  //! State the hook carries from step to step, for checkpoints (under `group`).
  virtual void save_state(CheckpointWriter&, const std::string& /*group*/) const {}
  virtual void load_state(const CheckpointReader&, const std::string& /*group*/) {}
};

}  // namespace pellicle
