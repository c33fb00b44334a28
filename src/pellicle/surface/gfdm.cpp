#include "pellicle/surface/gfdm.hpp"

#include <algorithm>
#include <limits>

#include <Eigen/Geometry>

#include "pellicle/core/error.hpp"
#include "pellicle/core/loop_failure.hpp"
#include "pellicle/pointcloud/local_fit.hpp"
#include "pellicle/surface/frames.hpp"

namespace pellicle {

namespace {

//! The weight exponents a stencil may use, narrowest first: the case's, then 4 and 2 where
//! they are broader.
struct WeightLadder {
  double exponent[3];
  int size = 0;
  explicit WeightLadder(const GfdmOptions& options) {
    exponent[size++] = options.weight_exponent;
    for (const double c : {4.0, kBroadWeightExponent})
      if (c < exponent[size - 1]) exponent[size++] = c;
  }
};

[[noreturn]] void unfit(std::size_t i, int count, FitStatus why) {
  throw NumericalError({0.0, 0, "surface", static_cast<long>(i)},
                       "point " + std::to_string(i) + " (" + std::to_string(count) +
                           " neighbours): " + describe(why) +
                           "; its second-order GFDM stencil is undefined (raise h or refine "
                           "the cloud there)");
}

//! How far a Laplacian stencil (column `col` of c, row 0 the point itself) is from a row of
//! an M-matrix: Σ_{j≠i} max(0, −c_j) / |c_i|, infinite when c_i is not negative.
template <int D, int M>
double negative_share(const FitCoefficients<D, M>& c, int count, int col) {
  if (!(c(0, col) < 0.0)) return std::numeric_limits<double>::infinity();
  double negative = 0.0;
  for (int k = 1; k < count; ++k) negative += std::max(0.0, -c(k, col));
  return negative / -c(0, col);
}

//! Fits `attempt(k, c)` for k = 0, 1, … until one's Laplacian (column `col`) has a negative
//! share of at most kMaxNegativeShare; otherwise keeps the one with the smallest share.
template <int D, int M, class Attempt>
FitStatus least_negative_fit(int attempts, int count, int col, FitCoefficients<D, M>& c,
                             Attempt attempt) {
  FitCoefficients<D, M> trial;
  FitStatus status = FitStatus::degenerate;
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < attempts; ++k) {
    const FitStatus s = attempt(k, trial);
    if (s != FitStatus::ok) {
      if (status != FitStatus::ok) status = s;
      continue;
    }
    const double share = negative_share<D, M>(trial, count, col);
    if (status != FitStatus::ok || share < best) {
      c = trial;
      best = share;
      status = FitStatus::ok;
    }
    if (share <= kMaxNegativeShare) break;
  }
  return status;
}

//! Δ_T at boundary point i with zero normal flux, ν · ∇_M u = 0, imposed exactly: the fit in
//! the tangent frame (ν, n × ν) has no slope along ν; at a corner the flux through both
//! edges is zero, so it has no slope at all (local_fit.hpp). Of the weights, the narrowest
//! that gives a stable row (negative_share); at a point where the boundary turns too gently
//! to be recognised as a corner, the corner's fit as the last resort
//! (docs/theory/surface-gfdm.md, "Boundary points").
template <int D>
FitStatus zero_flux_laplacian(const PointCloud<D>& cloud, std::size_t i, const Vec<D>& nu,
                              bool corner, const Vec<D>* offsets, int count, double h,
                              const WeightLadder& ladder, const FitTargets<D, 1>& laplacian,
                              double* coefficients) {
  constexpr int T = D - 1;
  Eigen::Matrix<double, D, T> along = cloud.frame[i].template leftCols<T>();
  if constexpr (D == 3) {
    const Vec3 n = cloud.normal(i);
    const Vec3 across = (nu - nu.dot(n) * n).normalized();
    along.col(0) = across;
    along.col(1) = n.cross(across);
  }
  // Edges: the ladder with one slope fixed, then the corner's fit under the broadest weight.
  const int attempts = ladder.size + (corner ? 0 : 1);
  FitCoefficients<D, 1> c;
  const FitStatus status =
      least_negative_fit<D, 1>(attempts, count, 0, c, [&](int k, FitCoefficients<D, 1>& out) {
        const double exponent = ladder.exponent[std::min(k, ladder.size - 1)];
        if (corner || k == ladder.size)
          return fit_coefficients<D, 1, T>(offsets, count, along, h, exponent, laplacian, out);
        return fit_coefficients<D, 1, 1>(offsets, count, along, h, exponent, laplacian, out);
      });
  if (status == FitStatus::ok)
    for (int k = 0; k < count; ++k) coefficients[k] = c(k, 0);
  return status;
}

//! Δ_T at a point on the rim of its part, where contact splits a surface that folds onto
//! itself (the sheet beyond the fold is another part, S_i^ext): the neighbourhood is
//! one-sided and no weight gives a Laplacian with a negative centre. The point takes the
//! boundary point's Laplacian, zero flux across the rim, with ν pointing away from its
//! neighbours (docs/theory/surface-contact.md, "Folds"); where even that is not negative
//! the stencil stays as it is and the repair removes the point (simulation.cpp).
template <int D>
void fold_laplacian(const PointCloud<D>& cloud, std::size_t i, const Vec<D>* offsets, int count,
                    double h, const WeightLadder& ladder, const FitTargets<D, 1>& target,
                    double* laplacian, double* zero_flux) {
  Vec<D> toward = Vec<D>::Zero();
  for (int k = 1; k < count; ++k) toward += offsets[k];
  const Vec<D> n = cloud.normal(i);
  const Vec<D> nu = (toward.dot(n) * n - toward).eval();
  if (!(nu.norm() > 1e-12 * h)) return;
  if (zero_flux_laplacian<D>(cloud, i, Vec<D>(nu.normalized()), false, offsets, count, h, ladder,
                             target, zero_flux) == FitStatus::ok)
    std::copy(zero_flux, zero_flux + count, laplacian);
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
  const WeightLadder ladder(options);
  const bool parts = cloud.has_parts();  // contact splits the neighbourhoods (folds below)
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
    // Interior points: of the weights, the narrowest whose Laplacian makes a stable implicit
    // row (negative_share; docs/theory/surface-gfdm.md). Boundary points keep the narrow
    // one: their rows use the zero-flux Laplacian below.
    FitCoefficients<D, T + 1> c;
    const FitStatus status =
        least_negative_fit<D, T + 1>(cloud.boundary[i] ? 1 : ladder.size, count, T, c,
                                     [&](int k, FitCoefficients<D, T + 1>& out) {
                                       return fit_coefficients<D, T + 1>(
                                           offsets, count, tangents, h, ladder.exponent[k], b, out);
                                     });
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
    if (!cloud.boundary[i]) {
      if (parts && !(c(0, T) < 0.0))
        fold_laplacian<D>(cloud, i, offsets, count, h, ladder, b.template rightCols<1>(),
                          st.laplacian.data() + nb.begin(i),
                          st.zero_flux_laplacian.data() + nb.begin(i));
      continue;
    }
    const FitStatus zero_flux = zero_flux_laplacian<D>(
        cloud, i, cloud.boundary_normal[i], cloud.corner[i] != 0, offsets, count, h, ladder,
        b.template rightCols<1>(), st.zero_flux_laplacian.data() + nb.begin(i));
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
