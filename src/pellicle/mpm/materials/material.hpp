#pragma once
//! The constitutive-model interface. A material updates all of its points in one call
//! (never one virtual call per point), from the velocity gradient the grid gives them.

#include <memory>
#include <string>
#include <vector>

#include "pellicle/core/parameters.hpp"
#include "pellicle/core/types.hpp"
#include "pellicle/mpm/particles.hpp"

namespace pellicle {

//! How a 2D run interprets the third direction; 3D runs use `solid`.
enum class Kinematics { plane_strain, plane_stress, axisymmetric, solid };

//! What a material needs for one step over the points [begin, end).
template <int D>
struct MaterialStep {
  Particles<D>& points;  //!< membrane points carry their current frames (normal, tangent)
  const std::vector<Mat<D>>& velocity_gradient;  //!< L_ij = ∂v_i/∂x_j at each point
  const std::vector<double>& hoop_rate;          //!< v_r/r (axisymmetric), else empty
  double dt;
  long begin, end;
  double cell = 0.0;  //!< grid cell size h (artificial viscosity length, thesis eq 4.12)
};

template <int D>
class Material {
 public:
  explicit Material(Kinematics kinematics) : kinematics_(kinematics) {}
  virtual ~Material() = default;

  //! Stress and strain update of the points over one step (objective rate, see each model).
  virtual void update(const MaterialStep<D>& step) const = 0;
  //! Largest signal speed over the points on cells of size `cell`, for the CFL time step
  //! (IJNME eq 19): the elastic wave speed for solids; for fluids the sound speed raised by
  //! the viscous terms (docs/theory/gas.md).
  virtual double max_signal_speed(const Particles<D>& points, long begin, long end,
                                  double cell) const = 0;
  //! Stored (recoverable) elastic energy of the points.
  virtual double strain_energy(const Particles<D>& points, long begin, long end) const = 0;
  //! Internal (thermal and compression) energy Σ m e of fluid points; 0 for solids.
  virtual double internal_energy(const Particles<D>&, long, long) const { return 0.0; }
  //! Volume-weighted mean pressure of the points, Σ V p / Σ V. Fluids report their
  //! equation-of-state pressure; solids the mean normal stress −tr σ / 3.
  virtual double mean_pressure(const Particles<D>& points, long begin, long end) const;
  //! Stress produced by a given strain from the unstressed state (initial strain input).
  virtual Sym<D> stress_from_strain(const Sym<D>& strain) const = 0;
  //! Reference mass density of the material.
  virtual double density() const = 0;
  //! Membrane models need a body of membrane points with frames; solids fill regions.
  virtual bool is_membrane() const { return false; }
  //! Rigid bodies move with a prescribed velocity and impose it on the grid nodes they touch.
  virtual bool is_rigid() const { return false; }
  //! Fluids (gas, liquids) carry a specific internal energy and report pressure and volume.
  virtual bool is_fluid() const { return false; }
  //! Fluids may take their point densities from cell densities (thesis eq 4.6) instead of
  //! the continuity equation.
  virtual bool density_from_cells() const { return false; }
  //! First point of [begin, end) whose state the model cannot continue from (a fluid's
  //! non-finite or, for a gas, negative internal energy), or −1.
  virtual long first_invalid_point(const Particles<D>&, long, long) const { return -1; }

  Kinematics kinematics() const { return kinematics_; }

 private:
  Kinematics kinematics_;
};

//! Builds one material from its parameter table.
template <int D>
using MaterialFactory = std::unique_ptr<Material<D>> (*)(ParameterReader& parameters,
                                                         Kinematics kinematics);

//! Known models by name (see registry.cpp: one line per model).
template <int D>
struct MaterialModel {
  std::string name;
  std::string summary;
  MaterialFactory<D> make;
};

template <int D>
const std::vector<MaterialModel<D>>& material_models();

template <int D>
double Material<D>::mean_pressure(const Particles<D>& points, long begin, long end) const {
  double pv = 0.0, v = 0.0;
  for (long p = begin; p < end; ++p) {
    pv -= points.volume[p] * trace<D>(points.stress[p]) / 3.0;
    v += points.volume[p];
  }
  return v > 0.0 ? pv / v : 0.0;
}

}  // namespace pellicle
