#pragma once
//! Weights of neighbours in the local fits of a point cloud, by their squared distance.

#include <cmath>

namespace pellicle {

//! Gaussian weight of a neighbour at distance r from a point of smoothing length h,
//! W = exp(−c r²/h²) (Suchde & Kuhnert): the surfaces' normals (eq 4), GFDM stencils
//! (eqs 19, 27) and interpolation (local_fit.hpp).
inline double gaussian_weight(double r_squared, double h, double c) {
  return std::exp(-c * r_squared / (h * h));
}

//! Compactly supported weight (1 − s)², s = r²/R² < 1, of a neighbour at distance r within a
//! radius R: the membranes' principal directions (normals/principal_directions.hpp). Callers
//! leave out neighbours with s ≥ 1.
inline double compact_weight(double s) {
  return (1 - s) * (1 - s);
}

}  // namespace pellicle
