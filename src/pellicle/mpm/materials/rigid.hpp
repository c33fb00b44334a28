#pragma once
//! A rigid body moving with a prescribed constant velocity (the body's `velocity`; zero holds
//! it fixed). Every grid node one of its points touches takes that velocity after the grid
//! solve, so it acts on other bodies as a moving wall of any shape (a ring holding a drum's
//! rim, an obstacle). It carries no stress and does not limit the time step.
//!
//! Case keys (table [[material]], model = "rigid"):
//!   density   kg/m³  > 0 (gives the points mass, which only matters for output)

#include <memory>

#include "pellicle/mpm/materials/material.hpp"

namespace pellicle {

template <int D>
class Rigid final : public Material<D> {
 public:
  Rigid(Kinematics kinematics, double density) : Material<D>(kinematics), density_(density) {}
  void declare_columns(Particles<D>&) override {}  //!< no state beyond position and velocity
  void update(const MaterialStep<D>&) const override {}
  double max_signal_speed(const Particles<D>&, long, long, double) const override { return 0.0; }
  double strain_energy(const Particles<D>&, long, long) const override { return 0.0; }
  Sym<D> stress_from_strain(const Sym<D>&) const override { return Sym<D>::Zero(); }
  double density() const override { return density_; }
  bool is_rigid() const override { return true; }

 private:
  double density_;
};

template <int D>
std::unique_ptr<Material<D>> make_rigid(ParameterReader& in, Kinematics kinematics) {
  return std::make_unique<Rigid<D>>(kinematics, in.number("density", NumberRange::positive()));
}

}  // namespace pellicle
