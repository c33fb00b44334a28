#include "pellicle/surface/gfdm.hpp"

#include <algorithm>

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
    const FitStatus status =
        fit_coefficients<D, T + 1>(offsets, count, tangents, h, options.weight_exponent, b, c);
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
    // h ν · ∇ of the monomials at the centre: ν's tangent components on the s_k entries.
    const Eigen::Matrix<double, T, 1> nu = tangents.transpose() * cloud.boundary_normal[i];
    FitCondition<D> zero_flux = FitCondition<D>::Zero();
    for (int t = 0; t < T; ++t) zero_flux(1 + t) = nu[t];
    FitTargets<D, 1> laplacian = b.template rightCols<1>();
    FitCoefficients<D, 1> cz;
    if (fit_coefficients<D, 1>(offsets, count, tangents, h, options.weight_exponent, laplacian, cz,
                               &zero_flux) != FitStatus::ok) {
      failure.record(i, static_cast<int>(FitStatus::degenerate));
      continue;
    }
    for (int k = 0; k < count; ++k) st.zero_flux_laplacian[nb.begin(i) + k] = cz(k, 0);
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
