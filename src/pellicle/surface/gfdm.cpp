#include "pellicle/surface/gfdm.hpp"

#include <Eigen/QR>

#include "pellicle/core/error.hpp"
#include "pellicle/surface/frames.hpp"

namespace pellicle {

namespace {

//! Monomials up to order 2 in the tangent coordinates s (scaled by h): 1, s, s² in 1D;
//! 1, s1, s2, s1², s1 s2, s2² in 2D.
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

[[noreturn]] void unfit(std::size_t i, int count, const char* why) {
  throw NumericalError({0.0, 0, "surface", static_cast<long>(i)},
                       "point " + std::to_string(i) + " (" + std::to_string(count) +
                           " neighbours): " + why +
                           "; its second-order GFDM stencil is undefined (raise h or refine "
                           "the cloud there)");
}

}  // namespace

template <int D>
void build_stencils(const PointCloud<D>& cloud, const NeighbourLists& nb,
                    const GfdmOptions& options, SurfaceStencils<D>& st) {
  constexpr int P = kMonomials<D>;
  constexpr int T = D - 1;  // dimension of the tangent space
  using Block = Eigen::Matrix<double, Eigen::Dynamic, P, Eigen::ColMajor, kMaxStencilPoints, P>;
  using Column = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxStencilPoints, 1>;
  const long n = static_cast<long>(cloud.size());
  st.gradient.resize(nb.index.size());
  st.laplacian.resize(nb.index.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (long i = 0; i < n; ++i) {
    const int count = nb.count(i);
    if (count > kMaxStencilPoints) unfit(i, count, "more neighbours than a stencil takes");
    if (count < P) unfit(i, count, "fewer neighbours than monomials to fit");
    const double h = cloud.smoothing_length[i];
    const Mat<D>& frame = cloud.frame[i];
    const auto tangents = frame.template leftCols<T>();
    Block a(count, P);
    Column w(count);
    for (int k = 0; k < count; ++k) {
      const Vec<D> d = cloud.position[nb.index[nb.begin(i) + k]] - cloud.position[i];
      // Projection along n_i onto the tangent plane, in units of h (§4.1.1, Fig. 12).
      const Eigen::Matrix<double, T, 1> s = tangents.transpose() * d / h;
      w[k] = gaussian_weight(d.squaredNorm(), h, options.weight_exponent);
      a.row(k) = w[k] * monomials<D>(s);
    }
    // c = W Q R^{-T} b minimises Σ (c/W)² subject to Mᵀ c = b (eqs 18–19, 26–27), with
    // A = W M = Q R.
    Eigen::HouseholderQR<Block> qr(a);
    const auto r = qr.matrixQR().template topRows<P>().template triangularView<Eigen::Upper>();
    const double largest = qr.matrixQR().diagonal().cwiseAbs().maxCoeff();
    if (qr.matrixQR().diagonal().cwiseAbs().minCoeff() < 1e-9 * largest)
      unfit(i, count, "its neighbours do not spread in every tangent direction");
    Eigen::Matrix<double, P, T + 1> b = Eigen::Matrix<double, P, T + 1>::Zero();
    for (int t = 0; t < T; ++t) b(1 + t, t) = 1.0 / h;  // ∂/∂t_k of s_k at s = 0
    // Δ_T of s_1² (and s_2²) at s = 0.
    b(1 + T, T) = 2.0 / (h * h);
    if constexpr (T == 2) b(5, T) = 2.0 / (h * h);
    const Eigen::Matrix<double, P, T + 1> y = r.transpose().solve(b);
    Eigen::Matrix<double, Eigen::Dynamic, T + 1, Eigen::ColMajor, kMaxStencilPoints, T + 1> e(
        count, T + 1);
    e.setZero();
    e.template topRows<P>() = y;
    e.applyOnTheLeft(qr.householderQ());
    for (int k = 0; k < count; ++k) {
      const long slot = nb.begin(i) + k;
      // Tangential derivatives rotated to x, y, z with c^n = 0 (eqs 21–22).
      st.gradient[slot] = w[k] * (tangents * e.row(k).template head<T>().transpose());
      st.laplacian[slot] = w[k] * e(k, T);  // rotation invariant: c^{Δ_M} = c^{Δ_T}
    }
  }
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
