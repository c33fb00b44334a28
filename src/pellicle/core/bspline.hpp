#pragma once
//! Uniform B-splines of order 1–3 on unit node spacing (the tent, quadratic and cubic
//! splines of Sulsky & York 2000 §5, centred on nodes). For a coordinate ξ each gives the
//! first node that supports ξ (`*_first`), the weights w and derivatives dw/dξ of the nodes
//! from that one on (`*_weights`), or both at once (the plain name, returning the first node).
//! Shared by the MPM kernels (mpm/shape) and the normal constructions (normals/).

namespace pellicle {

//! ⌊x⌋ as an int, for |x| within int's range: equal to std::floor there, and inlined (without
//! SSE4.1, std::floor is a library call, which costs more than the rest of a weight).
inline int floor_to_int(double x) {
  const int truncated = static_cast<int>(x);
  return truncated - (x < truncated ? 1 : 0);
}

//! Linear tent, 2 nodes.
inline int linear_bspline_first(double xi) {
  return floor_to_int(xi);
}
inline void linear_bspline_weights(double xi, int first, double* w, double* dw) {
  const double f = xi - first;
  w[0] = 1.0 - f;
  w[1] = f;
  dw[0] = -1.0;
  dw[1] = 1.0;
}
inline int linear_bspline(double xi, double* w, double* dw) {
  const int first = linear_bspline_first(xi);
  linear_bspline_weights(xi, first, w, dw);
  return first;
}

//! Quadratic B-spline, 3 nodes.
inline int quadratic_bspline_first(double xi) {
  return floor_to_int(xi - 0.5);
}
inline void quadratic_bspline_weights(double xi, int first, double* w, double* dw) {
  const double f = xi - first;  // in [0.5, 1.5)
  w[0] = 0.5 * (1.5 - f) * (1.5 - f);
  w[1] = 0.75 - (f - 1.0) * (f - 1.0);
  w[2] = 0.5 * (f - 0.5) * (f - 0.5);
  dw[0] = f - 1.5;
  dw[1] = -2.0 * (f - 1.0);
  dw[2] = f - 0.5;
}
inline int quadratic_bspline(double xi, double* w, double* dw) {
  const int first = quadratic_bspline_first(xi);
  quadratic_bspline_weights(xi, first, w, dw);
  return first;
}

//! Cubic B-spline, 4 nodes.
inline int cubic_bspline_first(double xi) {
  return floor_to_int(xi) - 1;
}
inline void cubic_bspline_weights(double xi, int first, double* w, double* dw) {
  const double f = xi - first;                                    // in [1, 2)
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
}
inline int cubic_bspline(double xi, double* w, double* dw) {
  const int first = cubic_bspline_first(xi);
  cubic_bspline_weights(xi, first, w, dw);
  return first;
}

}  // namespace pellicle
