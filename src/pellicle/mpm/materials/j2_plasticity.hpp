#pragma once
//! J2 (von Mises) plasticity with linear isotropic hardening, integrated by radial return
//! (docs/theory/plasticity.md). The stress is carried by the Jaumann rate as in
//! `linear-elastic` (IJNME 1999 eqs 12–15) and returned to the yield surface every step:
//!   σ̂ = σ^k + Δt (W σ^k − σ^k W)                    (P2), kinematics.hpp
//!   σ_tr = σ̂ + C : Δε,  f_tr = q(σ_tr) − σ_y(ε̄p)     (P3)–(P6)
//!   f_tr > 0: radial return (P8)–(P10); plane stress: the σ_zz = 0 return (P11)–(P15).
//! 2D runs use plane strain (Δε_zz = 0), plane stress (σ_zz = 0, the thickness strain follows)
//! or axisymmetry (Δε_θθ = Δt v_r/r); 3D runs are solid.
//!
//! Per-point state: the equivalent plastic strain ε̄p (P7) in the declared column
//! `plastic_strain` (dimensionless, written to snapshots and checkpoints), beside the total
//! small strain `strain` the base class declares.
//!
//! An `initial_strain` is taken as elastic (its stress is C : ε); a starting stress outside
//! the yield surface is returned to it in the first step.
//!
//! Case keys (table [[material]], model = "j2-plasticity"):
//!   density            kg/m³  > 0
//!   youngs_modulus     Pa     > 0
//!   poisson_ratio      –      in (−1, 0.5), default 0
//!   yield_stress       Pa     > 0             initial uniaxial yield stress σ_y0
//!   hardening_modulus  Pa     ≥ 0, default 0  H = dσ_y/dε̄p (0: perfect plasticity)

#include <memory>

#include "pellicle/mpm/materials/j2_return_mapping.hpp"
#include "pellicle/mpm/materials/linear_elastic.hpp"
#include "pellicle/mpm/materials/material.hpp"

namespace pellicle {

template <int D>
class J2Plasticity final : public Material<D> {
 public:
  //! Name of the declared column of ε̄p (snapshot array, checkpoint dataset).
  static constexpr const char* plastic_strain_column = "plastic_strain";

  //! Precondition: j2_supports<D>(kinematics) and the ranges above (the factory checks them).
  J2Plasticity(Kinematics kinematics, double density, const J2Constants& constants);

  //! The base class's `strain`, and `plastic_strain`.
  void declare_columns(Particles<D>& points) override;
  void update(const MaterialStep<D>& step) const override;
  double max_signal_speed(const Particles<D>& points, long begin, long end,
                          double cell) const override;
  //! Σ V ½ σ : C⁻¹ : σ, the recoverable elastic energy (P16); plastic work is not in it.
  double strain_energy(const Particles<D>& points, long begin, long end) const override;
  //! The elastic stress C : ε (P1), σ_zz = 0 in plane stress.
  Sym<D> stress_from_strain(const Sym<D>& strain) const override;
  double density() const override { return density_; }

  const J2Constants& constants() const { return constants_; }
  //! Modulus M with c = sqrt(M/ρ): the elastic P-wave modulus, or E/(1−ν²) in plane stress.
  //! The elastic–plastic tangent is never stiffer, so the elastic speed bounds the CFL step.
  double wave_modulus() const { return elastic_.wave_modulus(); }

 private:
  double density_;
  J2Constants constants_;
  LinearElastic<D> elastic_;  //!< the elastic part: C : ε and the wave modulus
  Column<double> plastic_strain_;
};

template <int D>
std::unique_ptr<Material<D>> make_j2_plasticity(ParameterReader& parameters, Kinematics kinematics);

extern template class J2Plasticity<2>;
extern template class J2Plasticity<3>;

}  // namespace pellicle
