#pragma once
//! Point kinematics shared by the constitutive models: strain increment and the Jaumann
//! rotation of a stress over one step (IJNME 1999 eqs 12–15), and the density that sets the
//! wave speed.

#include <algorithm>

#include "pellicle/core/types.hpp"
#include "pellicle/mpm/particles.hpp"

namespace pellicle {

//! Δε = Δt sym(L) (eq 12), with the hoop component Δt v_r/r in axisymmetry (0 otherwise).
//! These helpers build their results from scalars the compiler can keep in registers, not
//! with Eigen's comma initialiser or small matrix products: a result written piecewise to
//! memory and read back as one vector stalls store forwarding (docs/theory/performance.md,
//! "Store forwarding").
template <int D>
inline Sym<D> strain_increment(const Mat<D>& L, double hoop_rate, double dt) {
  if constexpr (D == 2) {
    return Sym<2>(dt * L(0, 0), dt * L(1, 1), dt * hoop_rate, dt * (0.5 * (L(0, 1) + L(1, 0))));
  } else {
    Sym<D> de;
    de[0] = dt * L(0, 0);
    de[1] = dt * L(1, 1);
    de[2] = dt * L(2, 2);
    de[3] = dt * (0.5 * (L(1, 2) + L(2, 1)));
    de[4] = dt * (0.5 * (L(0, 2) + L(2, 0)));
    de[5] = dt * (0.5 * (L(0, 1) + L(1, 0)));
    return de;
  }
}

//! σ + Δt (W σ − σ W), W = ½ (L − Lᵀ): the rotational part of the Jaumann update (eq 14).
//! Always inlined: in 3D GCC otherwise calls it, with σ and L passed through memory.
template <int D>
[[gnu::always_inline]] inline Sym<D> jaumann_rotate(const Sym<D>& s, const Mat<D>& L, double dt) {
  if constexpr (D == 2) {
    const double w = 0.5 * dt * (L(1, 0) - L(0, 1));  // W_yx Δt
    return Sym<2>(s[0] - 2.0 * w * s[3], s[1] + 2.0 * w * s[3], s[2], s[3] + w * (s[0] - s[1]));
  } else {
    const double half_dt = 0.5 * dt;
    double W[3][3], S[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) W[i][j] = half_dt * (L(i, j) - L(j, i));
    const int component[3][3] = {{0, 5, 4}, {5, 1, 3}, {4, 3, 2}};  // to_mat3's layout
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) S[i][j] = s[component[i][j]];
    // (W S − S W)_ij, each product summed over k in order
    const auto rate = [&](int i, int j) {
      return (W[i][0] * S[0][j] + W[i][1] * S[1][j] + W[i][2] * S[2][j]) -
             (S[i][0] * W[0][j] + S[i][1] * W[1][j] + S[i][2] * W[2][j]);
    };
    Sym<D> r;
    r[0] = s[0] + rate(0, 0);
    r[1] = s[1] + rate(1, 1);
    r[2] = s[2] + rate(2, 2);
    r[3] = s[3] + 0.5 * (rate(1, 2) + rate(2, 1));
    r[4] = s[4] + 0.5 * (rate(0, 2) + rate(2, 0));
    r[5] = s[5] + 0.5 * (rate(0, 1) + rate(1, 0));
    return r;
  }
}

//! Smallest current density of points [begin, end), and at most `reference`: the fastest
//! elastic wave, sqrt(M/ρ), is where the material is least dense. Serial, like the update it
//! follows (Material::max_signal_speed).
template <int D>
inline double smallest_density(const Particles<D>& points, long begin, long end, double reference) {
  // Four running minima, so that each comparison does not wait on the one before (the
  // minimum of a set does not depend on the order; densities here are positive and finite).
  double smallest[4] = {reference, reference, reference, reference};
  const double* density = points.density.data();
  long p = begin;
  for (; p + 4 <= end; p += 4)
    for (int k = 0; k < 4; ++k) smallest[k] = std::min(smallest[k], density[p + k]);
  for (; p < end; ++p) smallest[0] = std::min(smallest[0], density[p]);
  return std::min(std::min(smallest[0], smallest[1]), std::min(smallest[2], smallest[3]));
}

}  // namespace pellicle
