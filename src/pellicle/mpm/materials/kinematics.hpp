#pragma once
//! Point kinematics shared by the constitutive models: strain increment and the Jaumann
//! rotation of a stress over one step (IJNME 1999 eqs 12–15), and the density that sets the
//! wave speed.

#include <algorithm>

#include "pellicle/core/types.hpp"
#include "pellicle/mpm/particles.hpp"

namespace pellicle {

//! Δε = Δt sym(L) (eq 12), with the hoop component Δt v_r/r in axisymmetry (0 otherwise).
//! The 2D forms build their results from values, not by writing coefficients one by one: a
//! result written piecewise to memory and read back as one vector stalls store forwarding
//! (docs/theory/performance.md, "Store forwarding").
template <int D>
inline Sym<D> strain_increment(const Mat<D>& L, double hoop_rate, double dt) {
  if constexpr (D == 2) {
    return Sym<2>(dt * L(0, 0), dt * L(1, 1), dt * hoop_rate, dt * (0.5 * (L(0, 1) + L(1, 0))));
  } else {
    Sym<D> de;
    de << L(0, 0), L(1, 1), L(2, 2), 0.5 * (L(1, 2) + L(2, 1)), 0.5 * (L(0, 2) + L(2, 0)),
        0.5 * (L(0, 1) + L(1, 0));
    return dt * de;
  }
}

//! σ + Δt (W σ − σ W), W = ½ (L − Lᵀ): the rotational part of the Jaumann update (eq 14).
template <int D>
inline Sym<D> jaumann_rotate(const Sym<D>& s, const Mat<D>& L, double dt) {
  if constexpr (D == 2) {
    const double w = 0.5 * dt * (L(1, 0) - L(0, 1));  // W_yx Δt
    return Sym<2>(s[0] - 2.0 * w * s[3], s[1] + 2.0 * w * s[3], s[2], s[3] + w * (s[0] - s[1]));
  } else {
    const Mat3 W = 0.5 * dt * (L - L.transpose());
    const Mat3 S = to_mat3<D>(s);
    return s + from_mat3<D>(W * S - S * W);
  }
}

//! Smallest current density of points [begin, end), and at most `reference`: the fastest
//! elastic wave, sqrt(M/ρ), is where the material is least dense.
template <int D>
inline double smallest_density(const Particles<D>& points, long begin, long end, double reference) {
  double smallest = reference;
#pragma omp parallel for reduction(min : smallest) schedule(static)
  for (long p = begin; p < end; ++p) smallest = std::min(smallest, points.density[p]);
  return smallest;
}

}  // namespace pellicle
