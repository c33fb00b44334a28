#pragma once
//! J2 (von Mises) plasticity with linear isotropic hardening at one point: the elastic
//! predictor and the return mapping of one step, the stored elastic energy and the plastic
//! work. Pure functions of the point's state; equations (P1)–(P17) are those of
//! docs/theory/plasticity.md.
//!
//! One step (backward Euler, small strain increments):
//!   σ_tr = σ̂_n + C : Δε                          elastic predictor (P3), σ̂_n already
//!                                                 Jaumann-rotated by the caller (P2)
//!   f_tr = q(σ_tr) − σ_y(ε̄p_n)                   yield function (P5)–(P6)
//!   f_tr ≤ 0: elastic; else radial return (P8)–(P10) in 3D, plane strain and axisymmetry,
//!   and the plane-stress return (P11)–(P14) when σ_zz = 0 is imposed.

#include <algorithm>
#include <cmath>

#include "pellicle/core/types.hpp"
#include "pellicle/mpm/materials/material.hpp"

namespace pellicle {

//! Material constants of J2 plasticity with linear isotropic hardening (P1), (P6).
//! Preconditions: young > 0, −1 < poisson < 0.5, yield_stress > 0, hardening ≥ 0.
struct J2Constants {
  double young;         //!< Young's modulus E
  double poisson;       //!< Poisson's ratio ν
  double yield_stress;  //!< initial yield stress σ_y0 (uniaxial)
  double hardening;     //!< H = dσ_y/dε̄p, linear isotropic hardening modulus (0: perfect)

  //! Shear modulus G = E / (2(1 + ν)) (P1).
  double shear() const { return young / (2.0 * (1.0 + poisson)); }
  //! Bulk modulus K = E / (3(1 − 2ν)) (P1).
  double bulk() const { return young / (3.0 * (1.0 - 2.0 * poisson)); }
  //! Lamé's first parameter λ = E ν / ((1 + ν)(1 − 2ν)) (P1).
  double lambda() const { return young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson)); }
};

//! State of a J2 point: the stress in stored Sym<D> form and the equivalent plastic strain
//! ε̄p (P7).
template <int D>
struct J2State {
  Sym<D> stress;
  double plastic_strain;
};

//! Current yield stress σ_y = σ_y0 + H ε̄p (P6).
inline double j2_yield_stress(const J2Constants& c, double plastic_strain) {
  return c.yield_stress + c.hardening * plastic_strain;
}

//! Von Mises equivalent stress q = sqrt(3/2 s : s), s the deviator of the stored stress (P4).
//! In 2D the stored zz component enters the deviator (0 in plane stress).
template <int D>
inline double von_mises_stress(const Sym<D>& stress) {
  const double mean = trace<D>(stress) / 3.0;
  const Sym<D> s = add_to_normal<D>(stress, -mean);
  return std::sqrt(1.5 * contract<D>(s, s));
}

//! Kinematics j2_update handles: `solid` in 3D; plane strain, plane stress and axisymmetry
//! in 2D.
template <int D>
constexpr bool j2_supports(Kinematics kinematics) {
  if constexpr (D == 3) {
    return kinematics == Kinematics::solid;
  } else {
    return kinematics != Kinematics::solid;
  }
}

namespace j2_detail {

//! 3D law on the stored components (3D, plane strain with Δε_zz = 0, axisymmetry with the
//! hoop increment in Δε[2]): elastic predictor (P3) and radial return (P8)–(P10).
template <int D>
J2State<D> radial_return(const J2State<D>& old, const Sym<D>& de, const J2Constants& c) {
  const double G = c.shear();
  const Sym<D> trial =
      add_to_normal<D>(old.stress + 2.0 * G * de, c.lambda() * trace<D>(de));  // (P3)

  const double mean = trace<D>(trial) / 3.0;
  Sym<D> s = add_to_normal<D>(trial, -mean);  // deviator s_tr (P4)
  const double q_trial = std::sqrt(1.5 * contract<D>(s, s));
  const double f = q_trial - j2_yield_stress(c, old.plastic_strain);  // (P5)
  if (f <= 0.0) return {trial, old.plastic_strain};

  // f > 0 implies q_trial > σ_y > 0, and 3G + H > 0 even for H = 0.
  const double dgamma = f / (3.0 * G + c.hardening);                // (P10)
  s *= 1.0 - 3.0 * G * dgamma / q_trial;                            // (P9)
  return {add_to_normal<D>(s, mean), old.plastic_strain + dgamma};  // pressure unchanged (P9)
}

//! Plane stress (σ_zz = 0) in 2D: plane-stress predictor (P11), return (P12)–(P13) with the
//! scalar consistency equation (P14) solved by safeguarded Newton, thickness strain (P15).
inline J2State<2> plane_stress_return(const J2State<2>& old, Sym<2>& de, const J2Constants& c) {
  const double E = c.young, nu = c.poisson, G = c.shear();
  const double cps = E / (1.0 - nu * nu);
  const double sxx = old.stress[0] + cps * (de[0] + nu * de[1]);  // (P11)
  const double syy = old.stress[1] + cps * (nu * de[0] + de[1]);
  const double sxy = old.stress[3] + 2.0 * G * de[3];

  // Mean in-plane stress p̄, half difference d and shear t of the trial (P12).
  const double p_tr = 0.5 * (sxx + syy), d_tr = 0.5 * (sxx - syy), t_tr = sxy;
  const double b2 = d_tr * d_tr + t_tr * t_tr;
  const double q_trial = std::sqrt(p_tr * p_tr + 3.0 * b2);
  const double sigma_y = j2_yield_stress(c, old.plastic_strain);
  if (q_trial - sigma_y <= 0.0) {
    de[2] = -nu / (1.0 - nu) * (de[0] + de[1]);  // (P15) with Δλ = 0
    J2State<2> out{Sym<2>(), old.plastic_strain};
    out.stress << sxx, syy, 0.0, sxy;
    return out;
  }

  // x = 2GΔλ: p̄ = p̄_tr / (1 + r x), (d, t) = (d, t)_tr / (1 + x) (P13).
  const double r = (1.0 + nu) / (3.0 * (1.0 - nu));
  const double h = c.hardening / (3.0 * G);
  const auto q_of = [&](double x) {
    const double a = p_tr / (1.0 + r * x), b = 1.0 / (1.0 + x);
    return std::sqrt(a * a + 3.0 * b2 * b * b);
  };
  // φ(x) = q(x) − σ_y(ε̄p_n) − H x q(x) / (3G), strictly decreasing, φ(0) > 0 (P14).
  // Bracket: q(x) ≤ q_tr / (1 + min(r, 1) x), so φ(x_hi) ≤ 0 at the x_hi below.
  double lo = 0.0, hi = (q_trial / sigma_y - 1.0) / std::min(r, 1.0);
  // Start from the 3D radial return's x = 3GΔγ/q, exact when p̄_tr = 0.
  const double dgamma0 = (q_trial - sigma_y) / (3.0 * G + c.hardening);
  double x = std::clamp(3.0 * G * dgamma0 / (sigma_y + c.hardening * dgamma0), lo, hi);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double a = 1.0 / (1.0 + r * x), b = 1.0 / (1.0 + x);
    const double q = std::sqrt(p_tr * p_tr * a * a + 3.0 * b2 * b * b);
    const double phi = q - sigma_y - h * x * q;
    if (std::abs(phi) <= 1e-14 * q) break;
    (phi > 0.0 ? lo : hi) = x;
    const double dq = -(p_tr * p_tr * r * a * a * a + 3.0 * b2 * b * b * b) / q;
    const double dphi = dq - h * (q + x * dq);  // < 0: q decreases, x q increases
    double next = x - phi / dphi;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // safeguard: bisect
    const bool converged = std::abs(next - x) <= 1e-15 * next;
    x = next;
    if (converged || hi - lo <= 4e-16 * hi) break;
  }

  const double p = p_tr / (1.0 + r * x), d = d_tr / (1.0 + x), t = t_tr / (1.0 + x);
  const double q = q_of(x);
  const double dgamma = x * q / (3.0 * G);  // Δγ = (2/3) q Δλ (P13)
  // Thickness strain: elastic −ν/E Δ(σ_xx + σ_yy) plus plastic Δλ s_zz = −x p̄ / (3G) (P15).
  de[2] = -nu / E * (2.0 * p - (old.stress[0] + old.stress[1])) - x * p / (3.0 * G);
  J2State<2> out{Sym<2>(), old.plastic_strain + dgamma};
  out.stress << p + d, p - d, 0.0, t;
  return out;
}

}  // namespace j2_detail

//! One step of J2 plasticity with linear isotropic hardening at a point.
//!
//! `old_rotated` is the state at the start of the step with its stress already Jaumann-rotated
//! by the caller (kinematics.hpp: jaumann_rotate, (P2)); `strain_increment` is Δε = Δt sym(L)
//! (kinematics.hpp: strain_increment), with Δε_zz = 0 in plane strain and the hoop increment
//! Δt v_r/r in axisymmetry. Returns the stress and ε̄p at the end of the step.
//!
//! 3D, plane strain and axisymmetry: full 3D law on the stored components and radial return,
//! closed form and exact for linear hardening (P8)–(P10). Plane stress (2D only): σ_zz = 0
//! at the end of the step, the return solved to round-off (P11)–(P14), and
//! strain_increment[2] set to the thickness strain increment (P15), as
//! LinearElastic::stress_increment does.
//!
//! Precondition: j2_supports<D>(kinematics), constants as documented in J2Constants.
template <int D>
J2State<D> j2_update(const J2State<D>& old_rotated, Sym<D>& strain_increment,
                     const J2Constants& constants, Kinematics kinematics) {
  if constexpr (D == 2) {
    if (kinematics == Kinematics::plane_stress) {
      return j2_detail::plane_stress_return(old_rotated, strain_increment, constants);
    }
  }
  return j2_detail::radial_return<D>(old_rotated, strain_increment, constants);
}

//! Stored elastic energy density ½ σ : C⁻¹ : σ = [(1 + ν) σ:σ − ν (tr σ)²] / (2E) (P16),
//! valid for every kinematics since the stored stress includes σ_zz.
template <int D>
inline double j2_elastic_energy_density(const Sym<D>& stress, const J2Constants& c) {
  const double tr = trace<D>(stress);
  return ((1.0 + c.poisson) * contract<D>(stress, stress) - c.poisson * tr * tr) / (2.0 * c.young);
}

//! Plastic work per unit volume over a step that took ε̄p from `plastic_strain_old` to
//! `plastic_strain_new`: ∫ σ_y dε̄p = σ_y(mid) Δγ, σ_y at the mean ε̄p of the step, exact
//! for linear hardening (P17). Energy that leaves the elastic store for good; the split into
//! heat σ_y0 Δγ and hardening (cold work) is in docs/theory/plasticity.md.
inline double j2_plastic_work(const J2Constants& c, double plastic_strain_old,
                              double plastic_strain_new) {
  const double mid = 0.5 * (plastic_strain_old + plastic_strain_new);
  return j2_yield_stress(c, mid) * (plastic_strain_new - plastic_strain_old);
}

}  // namespace pellicle
