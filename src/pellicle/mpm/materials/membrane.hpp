#pragma once
//! Membranes and strings: stress only in the tangent plane (thesis ch. 5; IJNME §3).
//! Every step, at each point (thesis §5.3 steps 7–8):
//!   ε̃ = R ε^k Rᵀ + Δε            total strain, global axes (thesis eq 5.1; §5.4.2: the
//!                                  total strain, not only the increment, is rotated); R is
//!                                  the smallest rotation from last step's normal to this
//!                                  step's, so the strain moves with the surface
//!   ε' = Q ε̃ Qᵀ                   in the local frame (1' tangent, 2' second in-surface
//!                                  direction — out of plane / hoop in 2D, t2 in 3D —, 3' normal)
//!   law on (ε'11, ε'22, ε'12)     uniaxial: σ'11 = E ε'11 (eqs 5.5, 5.9);
//!                                 plane stress: σ'αβ = E/(1−ν²)[(1−ν) ε'αβ + ν δαβ ε'γγ]
//!                                 (eqs 5.12–5.15)
//!   out-of-surface strains adjusted to the law (uniaxial: ε'22 = ε'33 = −ν ε'11, eq 5.6;
//!   plane stress: ε'33 = −ν/(1−ν)(ε'11 + ε'22)), transverse shears zero
//!   σ = Qᵀ σ' Q, ε^{k+1} = Qᵀ ε'_adjusted Q   back to global axes for the internal force.
//! One-way (wrinkling) option (IJNME §3.2, thesis §5.2): no stiffness in compression; the
//! strain keeps accumulating. In plane stress it acts on principal in-plane strains
//! (tension-field theory): taut if the smaller principal stress is ≥ 0, wrinkled (uniaxial
//! tension E e1 along the larger principal direction) if only e1 > 0, slack otherwise.
//!
//! Case keys (table [[material]], model = "membrane"):
//!   density         kg/m³  > 0
//!   youngs_modulus  Pa     > 0
//!   poisson_ratio   –      in (−1, 0.5), default 0
//!   law             "uniaxial" (string, spring) or "plane-stress" (surface); default
//!                   "uniaxial" in 2D, "plane-stress" in 3D
//!   one_way         true/false, default false: wrinkling (no compressive stress)

#include <memory>

#include "pellicle/mpm/materials/material.hpp"

namespace pellicle {

enum class MembraneLaw { uniaxial, plane_stress };

//! Rotation to a membrane point's local axes (rows): 1' tangent, 2' second in-surface
//! direction (2D: z, the out-of-plane or hoop direction; 3D: n × t), 3' normal.
Mat3 membrane_axes(const Vec2& tangent, const Vec2& normal);
Mat3 membrane_axes(const Vec3& tangent, const Vec3& normal);
//! The smallest rotation taking unit normal `from` to `to` or to −`to`, whichever is nearer
//! (a surface's normal and its negative describe the same tangent plane).
Mat3 normal_transport(const Vec2& from, const Vec2& to);
Mat3 normal_transport(const Vec3& from, const Vec3& to);

template <int D>
class Membrane final : public Material<D> {
 public:
  //! `surface_volume`: a point's volume follows the stretch within the membrane (its length
  //! or area × a fixed thickness); false: the velocity divergence, as every other point (the
  //! seeds' algorithm).
  Membrane(Kinematics kinematics, double density, double youngs_modulus, double poisson_ratio,
           MembraneLaw law, bool one_way, bool surface_volume = true);

  //! The strain and the frame (normal, tangent) its body's estimator sets each step.
  void declare_columns(Particles<D>& points) override;
  void update(const MaterialStep<D>& step) const override;
  double max_signal_speed(const Particles<D>& points, long begin, long end,
                          double cell) const override;
  double strain_energy(const Particles<D>& points, long begin, long end) const override;
  //! A membrane's stress depends on its frame: it is set by the first update (zero here).
  Sym<D> stress_from_strain(const Sym<D>& strain) const override;
  double density() const override { return density_; }
  bool is_membrane() const override { return true; }
  bool stress_from_state() const override { return true; }
  //! Strain and stress in the local axes (11, 22, 12).
  std::vector<SnapshotField> snapshot_fields() const override {
    return {{"membrane_strain", 3}, {"membrane_stress", 3}};
  }
  void snapshot_values(int field, const Particles<D>& points, long begin, long end,
                       double* out) const override;

  //! The local law: in-surface strains (e11, e22, e12) to stresses (s11, s22, s12). With
  //! no stress allowed in direction 2' (strings; membranes of 2D plane-stress runs) e22 is
  //! set to the uniaxial value −ν e11.
  void local_stress(double e11, double& e22, double e12, double& s11, double& s22,
                    double& s12) const;
  //! Modulus M of the membrane wave speed sqrt(M/ρ).
  double wave_modulus() const;

 private:
  double density_, young_, poisson_;
  Column<Vec<D>> normal_, tangent_;
  Column<Vec<D>> strain_normal_;  //!< the normal the stored strain was last resolved about
  bool uniaxial_;                 //!< law uniaxial, or a plane-stress law in a 2D plane-stress run
  bool one_way_;
  bool surface_volume_;
};

template <int D>
std::unique_ptr<Material<D>> make_membrane(ParameterReader& parameters, Kinematics kinematics);

extern template class Membrane<2>;
extern template class Membrane<3>;

}  // namespace pellicle
