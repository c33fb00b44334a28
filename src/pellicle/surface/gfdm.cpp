#include "pellicle/surface/gfdm.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include <Eigen/Geometry>

#include "pellicle/core/error.hpp"
#include "pellicle/core/loop_failure.hpp"
#include "pellicle/surface/local_fit.hpp"

namespace pellicle {

namespace {

[[noreturn]] void unfit(std::size_t i, int count, FitStatus why) {
  throw NumericalError({0.0, 0, "surface", static_cast<long>(i)},
                       "point " + std::to_string(i) + " (" + std::to_string(count) +
                           " neighbours): " + describe(why) +
                           "; its second-order GFDM stencil is undefined (raise h or refine "
                           "the cloud there)");
}

//! Δ_T at boundary point i with zero normal flux, ν · ∇_M u = 0, imposed exactly: the fit in
//! the tangent frame (ν, n × ν) has no slope along ν; at a corner the flux through both
//! edges is zero, so it has no slope at all (local_fit.hpp). Its centre coefficient must be
//! negative, or implicit diffusion amplifies there (the row 1/Δt − α c_ii changes sign once
//! α Δt c_ii > 1). One-sided neighbourhoods under the narrow weight can give c_ii > 0, so
//! such a fit is redone with the broad weight, and then, for a point where the boundary
//! turns too gently to be recognised as a corner, as a corner (docs/theory/surface-gfdm.md).
//! When every fit leaves c_ii ≥ 0 the last one is stored (SparseSystem::solve refuses a
//! row that such a stencil makes non-positive).
template <int D>
FitStatus zero_flux_laplacian(const PointCloud<D>& cloud, std::size_t i, const Vec<D>* offsets,
                              int count, double h, const GfdmOptions& options,
                              const FitTargets<D, 1>& laplacian, double* coefficients) {
  constexpr int T = D - 1;
  Eigen::Matrix<double, D, T> along = cloud.frame[i].template leftCols<T>();
  if constexpr (D == 3) {
    const Vec3 n = cloud.normal(i);
    const Vec3 nu = cloud.boundary_normal[i];
    const Vec3 across = (nu - nu.dot(n) * n).normalized();
    along.col(0) = across;
    along.col(1) = n.cross(across);
  }
  FitCoefficients<D, 1> c;
  FitStatus status = FitStatus::ok;
  // One fit with `flat` slopes fixed; true when it is usable (c_ii < 0; row 0: the point).
  const auto stable_fit = [&](int flat, double exponent) {
    status = flat == 1
                 ? fit_coefficients<D, 1, 1>(offsets, count, along, h, exponent, laplacian, c)
                 : fit_coefficients<D, 1, T>(offsets, count, along, h, exponent, laplacian, c);
    return status == FitStatus::ok && c(0, 0) < 0.0;
  };
  const double narrow = options.weight_exponent, broad = kBroadWeightExponent;
  using Attempt = std::pair<int, double>;  // (flat slopes, weight exponent)
  const std::array<Attempt, 3> order = cloud.corner[i]
                                           ? std::array<Attempt, 3>{{{T, narrow}, {T, broad}}}
                                           : std::array<Attempt, 3>{{{1, narrow}, {1, broad}, {T, broad}}};
  const int tries = cloud.corner[i] ? 2 : 3;
  for (int k = 0; k < tries && !stable_fit(order[k].first, order[k].second); ++k) {
  }
  if (status == FitStatus::ok)
    for (int k = 0; k < count; ++k) coefficients[k] = c(k, 0);
  return status;
}

}  // namespace

template <int D>
void build_stencils(const PointCloud<D>& cloud, const NeighbourLists& nb,
                    const GfdmOptions& options, SurfaceStencils<D>& st) {
  constexpr int T = D - 1;  // dimension of the tangent space
  const long n = static_cast<long>(cloud.size());
  st.gradient.resize(nb.index.size());
  st.laplacian.resize(nb.index.size());
  st.zero_flux_laplacian.resize(nb.index.size());
  LoopFailure failure;
#pragma omp parallel for schedule(dynamic, 256)
  for (long i = 0; i < n; ++i) {
    const int count = nb.count(i);
    const auto tangents = cloud.frame[i].template leftCols<T>();
    Vec<D> offsets[kMaxStencilPoints];
    double farthest = 0.0;
    for (int k = 0; k < std::min(count, kMaxStencilPoints); ++k) {
      offsets[k] = cloud.position[nb.index[nb.begin(i) + k]] - cloud.position[i];
      farthest = std::max(farthest, offsets[k].norm());
    }
    // A neighbourhood widened beyond h (neighbours.hpp) weighs over its own reach.
    const double h = std::max(cloud.smoothing_length[i], farthest);
    // Targets: ∂/∂t_k (eq 18) and Δ_T (eq 26) of the monomials at the centre.
    FitTargets<D, T + 1> b = FitTargets<D, T + 1>::Zero();
    for (int t = 0; t < T; ++t) b(1 + t, t) = 1.0 / h;
    b(1 + T, T) = 2.0 / (h * h);
    if constexpr (T == 2) b(5, T) = 2.0 / (h * h);
    FitCoefficients<D, T + 1> c;
    FitStatus status =
        fit_coefficients<D, T + 1>(offsets, count, tangents, h, options.weight_exponent, b, c);
    // A Laplacian whose centre coefficient is not negative (row 0: the point itself) would
    // make implicit diffusion amplify there; an uneven, sparse neighbourhood under the
    // narrow weight can give one. The broad weight spreads the fit over the neighbourhood.
    if (status == FitStatus::ok && c(0, T) >= 0.0)
      status = fit_coefficients<D, T + 1>(offsets, count, tangents, h, kBroadWeightExponent, b, c);
    if (status != FitStatus::ok) {
      failure.record(i, static_cast<int>(status));
      continue;
    }
    for (int k = 0; k < count; ++k) {
      const long slot = nb.begin(i) + k;
      // Tangential derivatives rotated to x, y, z with c^n = 0 (eqs 21–22).
      st.gradient[slot] = tangents * c.row(k).template head<T>().transpose();
      st.laplacian[slot] = c(k, T);  // rotation invariant: c^{Δ_M} = c^{Δ_T}
      st.zero_flux_laplacian[slot] = c(k, T);
    }
    if (!cloud.boundary[i]) continue;
    const FitStatus zero_flux =
        zero_flux_laplacian<D>(cloud, i, offsets, count, h, options, b.template rightCols<1>(),
                               st.zero_flux_laplacian.data() + nb.begin(i));
    if (zero_flux != FitStatus::ok) failure.record(i, static_cast<int>(zero_flux));
  }
  if (failure.failed())
    unfit(failure.index(), nb.count(failure.index()), static_cast<FitStatus>(failure.detail()));
}

template <int D>
void refine_normals(PointCloud<D>& cloud, const NeighbourLists& nb, const SurfaceStencils<D>& st) {
  const long n = static_cast<long>(cloud.size());
  std::vector<Vec<D>> refined(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const Vec<D> normal = cloud.normal(i);
    Vec<D> slope = Vec<D>::Zero();
    for (long k = nb.begin(i); k < nb.end(i); ++k)
      slope += st.gradient[k] * normal.dot(cloud.position[nb.index[k]] - cloud.position[i]);
    refined[i] = (normal - slope).normalized();
  }
  for (long i = 0; i < n; ++i) {
    set_normal<D>(cloud.frame[i], refined[i]);
    if (cloud.boundary[i]) {  // ν stays in the (new) tangent space
      Vec<D>& nu = cloud.boundary_normal[i];
      nu = (nu - nu.dot(refined[i]) * refined[i]).normalized();
    }
  }
}

template <int D>
void mean_curvature(const PointCloud<D>& cloud, const NeighbourLists& nb,
                    const SurfaceStencils<D>& st, std::vector<double>& kappa) {
  const long n = static_cast<long>(cloud.size());
  kappa.resize(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    double div = 0.0;
    for (long k = nb.begin(i); k < nb.end(i); ++k)
      div += st.gradient[k].dot(cloud.normal(nb.index[k]));
    kappa[i] = -div / (D - 1);
  }
}

template void build_stencils<2>(const PointCloud<2>&, const NeighbourLists&, const GfdmOptions&,
                                SurfaceStencils<2>&);
template void build_stencils<3>(const PointCloud<3>&, const NeighbourLists&, const GfdmOptions&,
                                SurfaceStencils<3>&);
template void refine_normals<2>(PointCloud<2>&, const NeighbourLists&, const SurfaceStencils<2>&);
template void refine_normals<3>(PointCloud<3>&, const NeighbourLists&, const SurfaceStencils<3>&);
template void mean_curvature<2>(const PointCloud<2>&, const NeighbourLists&,
                                const SurfaceStencils<2>&, std::vector<double>&);
template void mean_curvature<3>(const PointCloud<3>&, const NeighbourLists&,
                                const SurfaceStencils<3>&, std::vector<double>&);

}  // namespace pellicle
