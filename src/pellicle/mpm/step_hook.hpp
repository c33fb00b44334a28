#pragma once
//! Hooks: what acts on the step at its named points without living in it — rigid bodies and
//! other boundary conditions (mpm/boundary/), contact models (mpm/contact/), and later halo
//! exchange. A new one is a class here plus its registration; step() does not change.

#include <string>
#include <utility>
#include <vector>

namespace pellicle {

template <int D>
class Simulation;

//! Named arrays a hook carries from one step to the next (written to checkpoints).
using HookState = std::vector<std::pair<std::string, std::vector<double>>>;

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
  //! Hooks that carry state from step to step name it (a checkpoint group); empty: none.
  virtual std::string state_name() const { return {}; }
  virtual HookState save_state() const { return {}; }
  //! Continue from a saved state; arrays the hook does not know are an error it throws.
  virtual void load_state(const HookState&) {}
};

}  // namespace pellicle
