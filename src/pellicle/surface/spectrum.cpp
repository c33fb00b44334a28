#include "pellicle/surface/spectrum.hpp"

#include <Spectra/GenEigsRealShiftSolver.h>
#include <Spectra/MatOp/SparseGenRealShiftSolve.h>
#include <Eigen/SparseCore>
#include <algorithm>

#include "pellicle/core/error.hpp"

namespace pellicle {

template <int D>
SpectrumReport laplace_beltrami_spectrum(const NeighbourLists& nb, const SurfaceStencils<D>& st,
                                         int count) {
  const long n = static_cast<long>(nb.points());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(nb.index.size());
  for (long i = 0; i < n; ++i)
    for (long k = nb.begin(i); k < nb.end(i); ++k)
      entries.emplace_back(i, nb.index[k], -st.laplacian[k]);
  Eigen::SparseMatrix<double> minus_laplacian(n, n);
  minus_laplacian.setFromTriplets(entries.begin(), entries.end());
  // Shift below zero: −Δ_M is singular on closed surfaces (the constants).
  const double shift = -0.1;
  Spectra::SparseGenRealShiftSolve<double> op(minus_laplacian);
  const int subspace = std::min<long>(n - 1, std::max(2 * count + 1, count + 20));
  Spectra::GenEigsRealShiftSolver<Spectra::SparseGenRealShiftSolve<double>> solver(op, count,
                                                                                   subspace, shift);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 2000, 1e-10);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw NumericalError({}, "the Laplace–Beltrami eigenvalue iterations did not converge");
  SpectrumReport r;
  for (const auto& lambda : solver.eigenvalues()) {
    r.eigenvalues.push_back(lambda.real());
    r.largest_imaginary = std::max(r.largest_imaginary, std::abs(lambda.imag()));
  }
  std::sort(r.eigenvalues.begin(), r.eigenvalues.end());
  return r;
}

template SpectrumReport laplace_beltrami_spectrum<2>(const NeighbourLists&,
                                                     const SurfaceStencils<2>&, int);
template SpectrumReport laplace_beltrami_spectrum<3>(const NeighbourLists&,
                                                     const SurfaceStencils<3>&, int);

}  // namespace pellicle
