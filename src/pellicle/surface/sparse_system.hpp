#pragma once
//! The sparse linear systems of implicit surface PDE steps: one row per point over its
//! neighbour list, solved by BiCGSTAB (van der Vorst) with an incomplete-LU preconditioner.
//! Eigen's sparse types stay inside sparse_system.cpp.

#include <memory>
#include <vector>

#include "pellicle/pointcloud/neighbour_search.hpp"

namespace pellicle {

//! Incomplete LU with threshold (fill factor 2, drop tolerance 1e-3), or the diagonal.
//! Measured on the implicit diffusion matrix of 7,500 points: ILU factorisation 20–26 ms
//! and 4–26 iterations, the diagonal 24–236 iterations (4–38 ms) as Δt grows from 0.004 to
//! 10; Eigen's default ILU (drop tolerance 1e-12) factorises in 154 ms.
enum class Preconditioner { ilu, jacobi };

struct LinearSolverOptions {
  double tolerance = 1e-10;  //!< relative residual |b − A x| / |b|
  int max_iterations = 500;
  Preconditioner preconditioner = Preconditioner::ilu;
};

struct LinearSolveReport {
  int iterations = 0;
  double residual = 0.0;
};

//! A matrix with the sparsity of the neighbour lists: coefficient k of `values` belongs to
//! row i and column index[k] for the k of point i's list.
class SparseSystem {
 public:
  SparseSystem();
  ~SparseSystem();
  SparseSystem(const SparseSystem&) = delete;
  SparseSystem& operator=(const SparseSystem&) = delete;

  //! Coefficients aligned with `lists` (filled by the caller, then `solve`).
  std::vector<double> values;
  //! Solve A x = rhs, starting from x. Throws NumericalError when a row's diagonal (the
  //! point itself, first in its list) is not positive, or BiCGSTAB does not reach the
  //! tolerance.
  LinearSolveReport solve(const NeighbourLists& lists, const std::vector<double>& rhs,
                          std::vector<double>& x, const LinearSolverOptions& options);

  struct Solver;

 private:
  std::unique_ptr<Solver> solver_;
};

}  // namespace pellicle
