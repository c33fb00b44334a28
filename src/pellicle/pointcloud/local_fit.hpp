#pragma once
//! The point-cloud layer's weighted local least-squares fit: a polynomial of order 2 in the
//! tangent coordinates of a local frame (local_frame.hpp), fitted to a centre's neighbours
//! with Gaussian weights. It is the constrained weighted least squares behind every GFDM
//! stencil (Suchde & Kuhnert eqs 18–19 and 26–27) and every moving-least-squares
//! interpolation to a new point: around a centre with a tangent frame and a smoothing length
//! h, find coefficients c_k of the neighbours' values that reproduce a linear functional (a
//! derivative at the centre, or the value there) of every monomial up to order 2 in the
//! tangent coordinates, minimising Σ_k (c_k / W_k)². (The membranes' isosurface fits,
//! normals/isosurface.hpp, are not of this kind: unweighted, in grid-cell B-splines rather
//! than a local frame, solved for nodal values by a rank-revealing QR.) Header-only so the
//! fixed-size loops inline where they are used.

#include <Eigen/QR>

#include "pellicle/core/types.hpp"
#include "pellicle/pointcloud/weights.hpp"

namespace pellicle {

//! Largest neighbourhood a fit takes (r_min = 0.2 allows about 100 points within h).
constexpr int kMaxStencilPoints = 160;

//! Monomials up to order 2 in the tangent coordinates s (in units of h): 1, s, s² on a
//! curve; 1, s1, s2, s1², s1 s2, s2² on a surface.
template <int D>
constexpr int kMonomials = D == 2 ? 3 : 6;

template <int D>
Eigen::Matrix<double, 1, kMonomials<D>> monomials(const Eigen::Matrix<double, D - 1, 1>& s) {
  Eigen::Matrix<double, 1, kMonomials<D>> m;
  if constexpr (D == 2)
    m << 1.0, s[0], s[0] * s[0];
  else
    m << 1.0, s[0], s[1], s[0] * s[0], s[0] * s[1], s[1] * s[1];
  return m;
}

//! b: one column per functional, its values on the monomials (e.g. ∂/∂s_1: (0, 1/h, 0, …)).
template <int D, int M>
using FitTargets = Eigen::Matrix<double, kMonomials<D>, M>;
//! One row per neighbour, one column per functional.
template <int D, int M>
using FitCoefficients =
    Eigen::Matrix<double, Eigen::Dynamic, M, Eigen::ColMajor, kMaxStencilPoints, M>;

enum class FitStatus { ok, too_few, too_many, degenerate };

//! Explains a failed fit in words for error messages.
inline const char* describe(FitStatus s) {
  switch (s) {
    case FitStatus::too_few:
      return "fewer neighbours than monomials to fit";
    case FitStatus::too_many:
      return "more neighbours than a stencil takes";
    case FitStatus::degenerate:
      return "its neighbours do not spread in every tangent direction";
    default:
      return "fit";
  }
}

//! `offsets[k]` = x_k − centre. Neighbours are projected along the normal onto the tangent
//! plane spanned by `tangents` (§4.1.1, Fig. 12). The solution is c = W Q R^{-T} b, with
//! A = W M = Q R (M the monomials at the neighbours, W their Gaussian weights). With
//! `FlatSlopes` = m > 0 the fitted quadratic has zero slope along the first m tangents at
//! the centre, exactly: their linear monomials are left out of M (and b must not ask for
//! those slopes). That is how a zero-flux boundary enters a fit (surface/gfdm.cpp).
template <int D, int M, int FlatSlopes = 0>
FitStatus fit_coefficients(const Vec<D>* offsets, int count,
                           const Eigen::Matrix<double, D, D - 1>& tangents, double h,
                           double weight_exponent, const FitTargets<D, M>& b,
                           FitCoefficients<D, M>& c) {
  static_assert(FlatSlopes >= 0 && FlatSlopes < D);
  // The constant, the free slopes, the quadratics.
  constexpr int kept = kMonomials<D> - FlatSlopes;
  using Block =
      Eigen::Matrix<double, Eigen::Dynamic, kept, Eigen::ColMajor, kMaxStencilPoints, kept>;
  if (count > kMaxStencilPoints) return FitStatus::too_many;
  if (count < kept) return FitStatus::too_few;
  Block a(count, kept);
  Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxStencilPoints, 1> w(count);
  for (int k = 0; k < count; ++k) {
    const Eigen::Matrix<double, D - 1, 1> s = tangents.transpose() * offsets[k] / h;
    w[k] = gaussian_weight(offsets[k].squaredNorm(), h, weight_exponent);
    const auto m = monomials<D>(s);  // the flat slopes are m[1 … FlatSlopes]
    a(k, 0) = w[k] * m[0];
    a.row(k).template tail<kept - 1>() = w[k] * m.template tail<kept - 1>();
  }
  Eigen::Matrix<double, kept, M> target;
  target.row(0) = b.row(0);
  target.template bottomRows<kept - 1>() = b.template bottomRows<kept - 1>();
  Eigen::HouseholderQR<Block> qr(a);
  const auto diagonal = qr.matrixQR().diagonal().cwiseAbs();
  if (diagonal.minCoeff() < 1e-9 * diagonal.maxCoeff()) return FitStatus::degenerate;
  const auto r = qr.matrixQR().template topRows<kept>().template triangularView<Eigen::Upper>();
  c.setZero(count, M);
  c.template topRows<kept>() = r.transpose().solve(target);
  c.applyOnTheLeft(qr.householderQ());
  for (int k = 0; k < count; ++k) c.row(k) *= w[k];
  return FitStatus::ok;
}

}  // namespace pellicle
