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
};

template <int D>
class Material {
 public:
  explicit Material(Kinematics kinematics) : kinematics_(kinematics) {}
  virtual ~Material() = default;

  //! Stress and strain update of the points over one step (objective rate, see each model).
  virtual void update(const MaterialStep<D>& step) const = 0;
  //! Largest signal speed over the points, for the CFL time step (IJNME eq 19).
  virtual double max_wave_speed(const Particles<D>& points, long begin, long end) const = 0;
  //! Stored (recoverable) energy of the points.
  virtual double strain_energy(const Particles<D>& points, long begin, long end) const = 0;
  //! Stress produced by a given strain from the unstressed state (initial strain input).
  virtual Sym<D> stress_from_strain(const Sym<D>& strain) const = 0;
  //! Reference mass density of the material.
  virtual double density() const = 0;
  //! Membrane models need a body of membrane points with frames; solids fill regions.
  virtual bool is_membrane() const { return false; }
  //! Rigid bodies move with a prescribed velocity and impose it on the grid nodes they touch.
  virtual bool is_rigid() const { return false; }

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

}  // namespace pellicle
