#pragma once
//! Update schemes: the order of the stages of one MPM step, chosen once at set-up
//! (thesis §3.3, IJNME §2.2; Buzzi et al. 2008 for the names). Each scheme is a strategy that
//! calls the stages of Stages; step() itself never branches on the scheme.

#include <memory>
#include <string>

namespace pellicle {

//! When the stress is updated relative to the grid solve.
enum class UpdateScheme {
  usf,   //!< update stress first, from the velocity mapped at the start of the step
  usl,   //!< update stress last, from the Lagrangian grid velocity
  musl,  //!< update stress last, from the convected (remapped) velocity — the seeds' scheme
};

//! The stages a scheme orders (implemented by Simulation).
class Stages {
 public:
  virtual ~Stages() = default;
  //! Scatter mass and momentum, and the forces when `forces`.
  virtual void to_grid(bool forces) = 0;
  //! USF: grid velocities p/m before the forces act; then the forces alone.
  virtual void grid_velocities() = 0;
  virtual void forces_to_grid() = 0;
  //! The momentum solve on every field, then the grid-update hooks.
  virtual void grid(double dt) = 0;
  virtual void to_points(double dt) = 0;
  //! MUSL: to_points, then the convected grid velocities from the updated points (the remap)
  //! and the grid-update hooks; the remap's scatter shares to_points' pass over the points
  //! unless a hook changes point velocities in between.
  virtual void to_points_and_remap(double dt) = 0;
  //! USL: to_points, and in the same pass over the points the velocity gradients of the
  //! velocities they moved with, which the materials stage then takes.
  virtual void to_points_and_gradients(double dt) = 0;
  //! Velocity gradients, densities, frames and each material's update.
  virtual void materials(double dt) = 0;
};

class Scheme {
 public:
  virtual ~Scheme() = default;
  //! Stages 3–7 of DESIGN.md's step, in this scheme's order.
  virtual void advance(Stages& stages, double dt) const = 0;
  //! Each body may move in its own grid field (contact models).
  virtual bool allows_body_fields() const { return true; }
  //! Its to_points keeps every point's velocity gradient for the materials stage.
  virtual bool keeps_gradients() const { return false; }
  virtual const char* name() const = 0;
};

std::unique_ptr<Scheme> make_scheme(UpdateScheme scheme);

}  // namespace pellicle
