#pragma once
//! Isotropic linear elasticity with the Jaumann stress rate (IJNME 1999 eqs 2 and 14):
//!   σ^{k+1} = σ^k + Δt (W σ^k − σ^k W) + C : Δε,   Δε = Δt sym(L),  W = skew(L).
//! 2D runs use plane strain (Δε_zz = 0), plane stress (σ_zz = 0) or axisymmetry
//! (Δε_θθ = Δt v_r/r).
//!
//! Case keys (table [[material]], model = "linear-elastic"):
//!   density         kg/m³  > 0
//!   youngs_modulus  Pa     > 0
//!   poisson_ratio   –      in (−1, 0.5)

#include <memory>

#include "pellicle/mpm/materials/material.hpp"

namespace pellicle {

template <int D>
class LinearElastic final : public Material<D> {
 public:
  LinearElastic(Kinematics kinematics, double density, double youngs_modulus, double poisson_ratio);

  void update(const MaterialStep<D>& step) const override;
  double max_signal_speed(const Particles<D>& points, long begin, long end,
                          double cell) const override;
  double strain_energy(const Particles<D>& points, long begin, long end) const override;
  Sym<D> stress_from_strain(const Sym<D>& strain) const override;
  double density() const override { return density_; }

  //! Δσ = C : Δε for the run's kinematics; for plane stress also sets Δε_zz.
  Sym<D> stress_increment(Sym<D>& strain_increment) const;
  //! Modulus M with c = sqrt(M/ρ): P-wave modulus, or E/(1−ν²) in plane stress.
  double wave_modulus() const;

 private:
  //! The constants of C : Δε as values: a loop holds them in registers, where members of
  //! `this` would be read again after every store to a column (they might alias).
  struct Law {
    bool plane_stress;
    double young, poisson, lambda, shear;
    //! stress_increment(), always inlined into the update loop: the increments then stay in
    //! registers.
    [[gnu::always_inline]] Sym<D> increment(Sym<D>& strain_increment) const;
  };
  Law law() const;
  template <bool Axisymmetric>
  static void update_points(Law law, const MaterialStep<D>& step, Sym<D>* stress, Sym<D>* strain);

  double density_, young_, poisson_, lambda_, shear_;
};

template <int D>
std::unique_ptr<Material<D>> make_linear_elastic(ParameterReader& parameters,
                                                 Kinematics kinematics);

extern template class LinearElastic<2>;
extern template class LinearElastic<3>;

}  // namespace pellicle
