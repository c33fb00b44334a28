#pragma once
//! The sparse linear systems of implicit surface PDE steps: one row per point over its
//! neighbour list, solved by BiCGSTAB (van der Vorst) with an incomplete-LU preconditioner.
//! Eigen's sparse types stay inside sparse_system.cpp.

#include <memory>
#include <vector>

#include "pellicle/surface/neighbours.hpp"

namespace pellicle {

struct LinearSolverOptions {
  double tolerance = 1e-10;  //!< relative residual |b − A x| / |b|
  int max_iterations = 500;
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
  //! Solve A x = rhs, starting from x. Throws NumericalError when BiCGSTAB does not reach the
  //! tolerance.
  LinearSolveReport solve(const NeighbourLists& lists, const std::vector<double>& rhs,
                          std::vector<double>& x, const LinearSolverOptions& options);

 private:
  struct Solver;
  std::unique_ptr<Solver> solver_;
};

}  // namespace pellicle
