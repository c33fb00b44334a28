#pragma once
//! Rows of the implicit systems shared by the surface PDEs: the operator a φ_i − b Δ_M φ_i
//! (at boundary points with zero normal flux built into Δ_M), or a prescribed value.

#include "pellicle/surface/gfdm.hpp"
#include "pellicle/surface/simulation.hpp"

namespace pellicle {

enum class SurfaceBoundary { zero_flux, dirichlet };

//! The row diagonal φ_i − factor Δ_M φ_i; at a boundary point with zero normal flux its
//! Laplacian is the one of the fit that has ν · ∇_M φ = 0 there (gfdm.hpp).
template <int D>
void operator_row(const NeighbourLists& nb, const SurfaceStencils<D>& st, std::size_t i,
                  double diagonal, double laplacian_factor, bool zero_flux,
                  std::vector<double>& values) {
  const std::vector<double>& laplacian = zero_flux ? st.zero_flux_laplacian : st.laplacian;
  for (long k = nb.begin(i); k < nb.end(i); ++k)
    values[k] = (k == nb.begin(i) ? diagonal : 0.0) - laplacian_factor * laplacian[k];
}

//! φ_i = value (the rhs).
inline void value_row(const NeighbourLists& nb, std::size_t i, std::vector<double>& values) {
  for (long k = nb.begin(i); k < nb.end(i); ++k) values[k] = k == nb.begin(i) ? 1.0 : 0.0;
}

}  // namespace pellicle
