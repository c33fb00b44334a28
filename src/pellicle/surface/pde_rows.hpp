#pragma once
//! Rows of the implicit systems shared by the surface PDEs: the interior operator
//! a φ_i − b Δ_M φ_i, and at boundary points either zero normal flux ν · ∇_M φ = 0 or a
//! prescribed value.

#include "pellicle/surface/gfdm.hpp"
#include "pellicle/surface/simulation.hpp"

namespace pellicle {

enum class SurfaceBoundary { zero_flux, dirichlet };

template <int D>
void interior_row(const NeighbourLists& nb, const SurfaceStencils<D>& st, std::size_t i,
                  double diagonal, double laplacian_factor, std::vector<double>& values) {
  for (long k = nb.begin(i); k < nb.end(i); ++k)
    values[k] = (k == nb.begin(i) ? diagonal : 0.0) - laplacian_factor * st.laplacian[k];
}

//! ν · ∇_M φ = 0 at boundary point i (rhs 0).
template <int D>
void zero_flux_row(const PointCloud<D>& cloud, const NeighbourLists& nb,
                   const SurfaceStencils<D>& st, std::size_t i, std::vector<double>& values) {
  for (long k = nb.begin(i); k < nb.end(i); ++k)
    values[k] = cloud.boundary_normal[i].dot(st.gradient[k]);
}

//! φ_i = value (the rhs).
inline void value_row(const NeighbourLists& nb, std::size_t i, std::vector<double>& values) {
  for (long k = nb.begin(i); k < nb.end(i); ++k) values[k] = k == nb.begin(i) ? 1.0 : 0.0;
}

}  // namespace pellicle
