#include "pellicle/mpm/scheme.hpp"

namespace pellicle {
namespace {

//! USF: the stress from the velocity mapped at the start of the step, before the grid solve.
class UpdateStressFirst final : public Scheme {
 public:
  void advance(Stages& s, double dt) const override {
    s.to_grid(false);
    s.grid_velocities();
    s.materials(dt);
    s.forces_to_grid();
    s.grid(dt);
    s.to_points(dt);
  }
  //! The mapped velocities it updates the stress from are not corrected by a contact rule.
  bool allows_body_fields() const override { return false; }
  const char* name() const override { return "usf"; }
};

//! USL: the stress from the Lagrangian grid velocity of this step.
class UpdateStressLast final : public Scheme {
 public:
  void advance(Stages& s, double dt) const override {
    s.to_grid(true);
    s.grid(dt);
    s.to_points_and_gradients(dt);
    s.materials(dt);
  }
  bool keeps_gradients() const override { return true; }
  const char* name() const override { return "usl"; }
};

//! MUSL: the stress from the grid velocity remapped from the updated points (thesis eq 3.24).
class ModifiedUpdateStressLast final : public Scheme {
 public:
  void advance(Stages& s, double dt) const override {
    s.to_grid(true);
    s.grid(dt);
    s.to_points_and_remap(dt);
    s.materials(dt);
  }
  const char* name() const override { return "musl"; }
};

}  // namespace

std::unique_ptr<Scheme> make_scheme(UpdateScheme scheme) {
  switch (scheme) {
    case UpdateScheme::usf:
      return std::make_unique<UpdateStressFirst>();
    case UpdateScheme::usl:
      return std::make_unique<UpdateStressLast>();
    case UpdateScheme::musl:
      break;
  }
  return std::make_unique<ModifiedUpdateStressLast>();
}

}  // namespace pellicle
