#pragma once
//! Meshfree GFDM surface operators (Suchde & Kuhnert §4.1): at every point, stencils for the
//! surface gradient (eqs 17–22) and the Laplace–Beltrami operator (eqs 25–27) from a
//! constrained weighted least-squares problem in the tangent plane. The neighbours are
//! projected along n_i onto the tangent plane; the stencil differentiates every monomial up
//! to order 2 in the tangent coordinates exactly (eq 18) and among those minimises
//! Σ_j (c_ij / W_ij)² (eq 19) with the Gaussian weight W of frames.hpp.

#include <vector>

#include "pellicle/pointcloud/neighbour_search.hpp"
#include "pellicle/surface/point_cloud.hpp"

namespace pellicle {

struct GfdmOptions {
  //! c of W = exp(−c r²/h²) (the paper does not give its width). With c = 2 the discrete
  //! Laplace–Beltrami operator of an irregular cloud has spurious eigenvalues (between 6 and
  //! 12 on the unit sphere at 6 points per h², negative ones at 9 and more); from c = 6 on
  //! there are none up to 20 points per h², and the eigenvalues are the more accurate the
  //! larger c (2.015, 2.009, 2.004 for c = 2, 4, 8 at h = 0.2): docs/theory/surface-gfdm.md.
  double weight_exponent = 8.0;
};

//! The broadest weight a stencil falls back to (gfdm.cpp): a Laplacian whose negative
//! off-diagonal coefficients outweigh kMaxNegativeShare of its (negative) centre
//! coefficient, or whose centre coefficient is not negative, is fitted again under broader
//! weights (4, then this), and the least negative one kept.
constexpr double kBroadWeightExponent = 2.0;
constexpr double kMaxNegativeShare = 0.5;

//! Stencil coefficients aligned with the neighbour lists they were built on: entry k of
//! point i's list holds the coefficients of u_j, j = index[k].
template <int D>
struct SurfaceStencils {
  std::vector<Vec<D>> gradient;   //!< (c^{M,x}, c^{M,y}, c^{M,z}) of eqs 20–21
  std::vector<double> laplacian;  //!< c^{Δ_M} of eq 25
  //! At boundary points: Δ_M of the fit that has zero normal flux, ν · ∇_M u = 0, at the
  //! point (no slope along ν; at a corner no slope at all, gfdm.cpp). A PDE row with it
  //! keeps its time-derivative diagonal where a row ν · ∇_M u = 0 would replace it.
  //! Elsewhere a copy of `laplacian`.
  std::vector<double> zero_flux_laplacian;
};

//! Build every point's stencils. Throws NumericalError naming the point when its
//! neighbourhood cannot fix a second-order fit (too few points, or all on one line).
template <int D>
void build_stencils(const PointCloud<D>& cloud, const NeighbourLists& neighbours,
                    const GfdmOptions& options, SurfaceStencils<D>& stencils);

//! ∇_M u at point i (eq 20).
template <int D>
Vec<D> surface_gradient(const NeighbourLists& nb, const SurfaceStencils<D>& st, std::size_t i,
                        const std::vector<double>& u) {
  Vec<D> g = Vec<D>::Zero();
  for (long k = nb.begin(i); k < nb.end(i); ++k) g += st.gradient[k] * u[nb.index[k]];
  return g;
}

//! Δ_M u at point i (eq 25).
template <int D>
double laplace_beltrami(const NeighbourLists& nb, const SurfaceStencils<D>& st, std::size_t i,
                        const std::vector<double>& u) {
  double l = 0.0;
  for (long k = nb.begin(i); k < nb.end(i); ++k) l += st.laplacian[k] * u[nb.index[k]];
  return l;
}

//! ∇_M · v at point i (eq 24).
template <int D>
double surface_divergence(const NeighbourLists& nb, const SurfaceStencils<D>& st, std::size_t i,
                          const std::vector<Vec<D>>& v) {
  double d = 0.0;
  for (long k = nb.begin(i); k < nb.end(i); ++k) d += st.gradient[k].dot(v[nb.index[k]]);
  return d;
}

//! Second-order normals: the eq 4 normal tilts by O(h) where the neighbours sit unevenly
//! around a curved point (the chords' normal components, |d|²κ/2, weigh in unevenly), so
//! its divergence (eq 37) and the tangent-plane projection of the stencils inherit an O(1)
//! and an O(h) error. The stencils' gradient of the heights ζ_j = n_i · (x_j − x_i) over
//! the tangent plane (exact for quadratics, eq 18) is the surface's slope there; tilting n_i
//! by it gives normals accurate to O(h²). Frames are rebuilt from the new normals (same
//! sides); the stencils must be built again after this. docs/theory/surface-gfdm.md.
template <int D>
void refine_normals(PointCloud<D>& cloud, const NeighbourLists& nb, const SurfaceStencils<D>& st);

//! Mean curvature κ = −∇_M · n / (D − 1) at every point: eq 37 for surfaces (−½ ∇_M · n),
//! the curvature −∇_M · n for curves. Negative on a sphere with outward normals.
template <int D>
void mean_curvature(const PointCloud<D>& cloud, const NeighbourLists& nb,
                    const SurfaceStencils<D>& st, std::vector<double>& kappa);

}  // namespace pellicle
