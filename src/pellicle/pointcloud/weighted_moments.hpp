#pragma once
//! The other weighted local fit of a point cloud: a normal as the direction of least spread of
//! the neighbours, the eigenvector of the smallest eigenvalue of their weighted second moments
//! M = Σ_k w_k d_k d_kᵀ (d_k = x_k − x_i, the offsets from the point, so no cancellation far
//! from the origin). The surfaces' normals take the uncentred moments with w = W/|d|² (Suchde &
//! Kuhnert eq 4: n minimises Σ W cos² of the angles to the neighbours); the membranes'
//! principal directions take the covariance about the weighted mean, M/Σw − d̄ d̄ᵀ (a weighted
//! total-least-squares plane or line, normals/principal_directions.hpp). Header-only: it runs
//! in the frame loops.

#include <Eigen/Eigenvalues>

#include "pellicle/core/types.hpp"

namespace pellicle {

//! Weighted moments of offsets d_k. With `Centred` also Σ w and Σ w d, for the covariance.
template <int D, bool Centred>
struct WeightedMoments {
  Mat<D> second = Mat<D>::Zero();  //!< Σ w d dᵀ
  Vec<D> first = Vec<D>::Zero();   //!< Σ w d (Centred only)
  double weight = 0.0;             //!< Σ w (Centred only)

  void add(const Vec<D>& d, double w) {
    if constexpr (Centred) {
      weight += w;
      first += w * d;
    }
    second += w * d * d.transpose();
  }
  //! Σ w d dᵀ, or (Centred) the covariance about the weighted mean.
  Mat<D> matrix() const {
    if constexpr (Centred) {
      const Vec<D> mean = first / weight;
      return second / weight - mean * mean.transpose();
    } else {
      return second;
    }
  }
};

//! Unit eigenvector of the smallest eigenvalue of a symmetric M (unsigned).
template <int D>
Vec<D> least_spread_direction(const Mat<D>& m) {
  return Eigen::SelfAdjointEigenSolver<Mat<D>>(m).eigenvectors().col(0);
}

}  // namespace pellicle
