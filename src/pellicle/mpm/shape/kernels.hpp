#pragma once
//! Shape-function kernels. Each is a 1D function of the point position in cell units; the
//! D-dimensional weight is the tensor product N_i(x) = Π_d φ(ξ_d − i_d) (thesis §3, eq 3.14 with
//! bilinear basis functions for the linear kernel). A kernel fills, for one coordinate, the
//! first node index of the stencil and `width` weights and weight derivatives.
//!
//! Coordinates are in cell units: ξ = (x − origin)/h. Derivatives returned are dφ/dξ; the
//! stencil scales them by 1/h. `first(ξ)` is the first node, `weights(ξ, first, …)` the
//! weights of the nodes from it on, and `fill` both.

#include <cmath>

#include "pellicle/core/bspline.hpp"

namespace pellicle::shape {

//! Linear tent (bilinear/trilinear FE basis), the kernel of the seeds. Support 2 nodes.
struct Linear {
  static constexpr int width = 2;
  static constexpr const char* name = "linear";
  //! APIC uses the gradient form C = Σ v_i ⊗ ∇N_i for this kernel (see docs/theory).
  static constexpr double apic_inertia = 0.0;
  inline int first(double xi) const { return linear_bspline_first(xi); }
  inline void weights(double xi, int first, double* w, double* dw) const {
    linear_bspline_weights(xi, first, w, dw);
  }
  inline int fill(double xi, double* w, double* dw) const { return linear_bspline(xi, w, dw); }
};

//! Uniform GIMP: the tent convolved with a particle characteristic function of half-width
//! `half_size` (in cell units, ≤ 1/2). Support 3 nodes.
struct UGimp {
  static constexpr int width = 3;
  static constexpr const char* name = "ugimp";
  static constexpr double apic_inertia = 0.0;
  double half_size = 0.25;  //!< l_p / h: 1/(2 × points per cell)

  inline double phi(double r) const {
    const double l = half_size;
    const double a = std::abs(r);
    if (a < l) return 1.0 - (r * r + l * l) / (2.0 * l);
    if (a < 1.0 - l) return 1.0 - a;
    if (a < 1.0 + l) return (1.0 + l - a) * (1.0 + l - a) / (4.0 * l);
    return 0.0;
  }
  inline double dphi(double r) const {
    const double l = half_size;
    const double a = std::abs(r);
    const double s = r < 0.0 ? -1.0 : 1.0;
    if (a < l) return -r / l;
    if (a < 1.0 - l) return -s;
    if (a < 1.0 + l) return -s * (1.0 + l - a) / (2.0 * l);
    return 0.0;
  }
  inline int first(double xi) const { return floor_to_int(xi + 0.5) - 1; }
  inline void weights(double xi, int first, double* w, double* dw) const {
    for (int a = 0; a < width; ++a) {
      const double r = xi - (first + a);
      w[a] = phi(r);
      dw[a] = dphi(r);
    }
  }
  inline int fill(double xi, double* w, double* dw) const {
    const int base = first(xi);
    weights(xi, base, w, dw);
    return base;
  }
};

//! Quadratic B-spline centred on nodes. Support 3 nodes. Inertia tensor D = h²/4 I.
struct QuadraticBSpline {
  static constexpr int width = 3;
  static constexpr const char* name = "quadratic-bspline";
  static constexpr double apic_inertia = 0.25;
  inline int first(double xi) const { return quadratic_bspline_first(xi); }
  inline void weights(double xi, int first, double* w, double* dw) const {
    quadratic_bspline_weights(xi, first, w, dw);
  }
  inline int fill(double xi, double* w, double* dw) const { return quadratic_bspline(xi, w, dw); }
};

//! Cubic B-spline centred on nodes. Support 4 nodes. Inertia tensor D = h²/3 I.
struct CubicBSpline {
  static constexpr int width = 4;
  static constexpr const char* name = "cubic-bspline";
  static constexpr double apic_inertia = 1.0 / 3.0;
  inline int first(double xi) const { return cubic_bspline_first(xi); }
  inline void weights(double xi, int first, double* w, double* dw) const {
    cubic_bspline_weights(xi, first, w, dw);
  }
  inline int fill(double xi, double* w, double* dw) const { return cubic_bspline(xi, w, dw); }
};

}  // namespace pellicle::shape
