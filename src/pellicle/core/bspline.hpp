#pragma once
//! Uniform B-splines of order 1–3 on unit node spacing (the tent, quadratic and cubic
//! splines of Sulsky & York 2000 §5, centred on nodes). For a coordinate ξ each fills the
//! weights w and derivatives dw/dξ of the nodes that support ξ and returns the first of them.
//! Shared by the MPM kernels (mpm/shape) and the normal constructions (normals/).

#include <cmath>

namespace pellicle {

//! Linear tent, 2 nodes.
inline int linear_bspline(double xi, double* w, double* dw) {
  const int base = static_cast<int>(std::floor(xi));
  const double f = xi - base;
  w[0] = 1.0 - f;
  w[1] = f;
  dw[0] = -1.0;
  dw[1] = 1.0;
  return base;
}

//! Quadratic B-spline, 3 nodes.
inline int quadratic_bspline(double xi, double* w, double* dw) {
  const int base = static_cast<int>(std::floor(xi - 0.5));
  const double f = xi - base;  // in [0.5, 1.5)
  w[0] = 0.5 * (1.5 - f) * (1.5 - f);
  w[1] = 0.75 - (f - 1.0) * (f - 1.0);
  w[2] = 0.5 * (f - 0.5) * (f - 0.5);
  dw[0] = f - 1.5;
  dw[1] = -2.0 * (f - 1.0);
  dw[2] = f - 0.5;
  return base;
}

//! Cubic B-spline, 4 nodes.
inline int cubic_bspline(double xi, double* w, double* dw) {
  const int base = static_cast<int>(std::floor(xi)) - 1;
  const double f = xi - base;                                     // in [1, 2)
  const double r0 = f, r1 = f - 1.0, r2 = 2.0 - f, r3 = 3.0 - f;  // |ξ − node|
  w[0] = (2.0 - r0) * (2.0 - r0) * (2.0 - r0) / 6.0;
  w[1] = 0.5 * r1 * r1 * r1 - r1 * r1 + 2.0 / 3.0;
  w[2] = 0.5 * r2 * r2 * r2 - r2 * r2 + 2.0 / 3.0;
  w[3] = (2.0 - r3) * (2.0 - r3) * (2.0 - r3) / 6.0;
  // d/dξ: nodes 0, 1 lie below ξ (r grows with ξ), nodes 2, 3 above (r shrinks).
  dw[0] = -0.5 * (2.0 - r0) * (2.0 - r0);
  dw[1] = 1.5 * r1 * r1 - 2.0 * r1;
  dw[2] = -(1.5 * r2 * r2 - 2.0 * r2);
  dw[3] = 0.5 * (2.0 - r3) * (2.0 - r3);
  return base;
}

}  // namespace pellicle
