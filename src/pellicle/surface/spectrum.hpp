#pragma once
//! Eigenvalues of the discrete Laplace–Beltrami operator of a cloud: −Δ_M u = λ u with the
//! GFDM stencils (eq 25), the smallest λ found by shift-invert Arnoldi iterations (Spectra)
//! around a shift just below zero. The stencils are not symmetric, so the eigenvalues may
//! carry small imaginary parts; their real parts are returned, ascending.

#include <vector>

#include "pellicle/surface/gfdm.hpp"

namespace pellicle {

struct SpectrumReport {
  std::vector<double> eigenvalues;  //!< real parts, ascending (λ₀ ≈ 0 on closed surfaces)
  double largest_imaginary = 0.0;   //!< max |Im λ| among them
};

//! The `count` eigenvalues of −Δ_M nearest to zero. Throws NumericalError when the
//! iterations do not converge.
template <int D>
SpectrumReport laplace_beltrami_spectrum(const NeighbourLists& neighbours,
                                         const SurfaceStencils<D>& stencils, int count);

}  // namespace pellicle
