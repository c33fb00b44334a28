#include "pellicle/surface/sparse_system.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <cstdio>

#include "pellicle/core/error.hpp"

namespace pellicle {

struct SparseSystem::Solver {
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  Matrix matrix;
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::BiCGSTAB<Matrix, Eigen::IncompleteLUT<double>> with_ilu;
  Eigen::BiCGSTAB<Matrix, Eigen::DiagonalPreconditioner<double>> with_diagonal;
};

namespace {
template <class Solver>
LinearSolveReport run(Solver& solver, const SparseSystem::Solver::Matrix& a,
                      const std::vector<double>& rhs, std::vector<double>& x,
                      const LinearSolverOptions& options) {
  solver.setTolerance(options.tolerance);
  solver.setMaxIterations(options.max_iterations);
  solver.compute(a);
  if (solver.info() != Eigen::Success)
    throw NumericalError({},
                         "the preconditioner of the implicit step's matrix could not be "
                         "built (a zero pivot: an isolated point or a singular stencil)");
  const long n = a.rows();
  const Eigen::Map<const Eigen::VectorXd> b(rhs.data(), n);
  Eigen::Map<Eigen::VectorXd> solution(x.data(), n);
  solution = solver.solveWithGuess(b, Eigen::VectorXd(solution));
  LinearSolveReport report{static_cast<int>(solver.iterations()), solver.error()};
  if (solver.info() != Eigen::Success || !std::isfinite(report.residual)) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "BiCGSTAB did not converge: relative residual %.3g after %d iterations "
                  "(tolerance %.3g); lower the time step or raise solver.max_iterations",
                  report.residual, report.iterations, options.tolerance);
    throw NumericalError({}, text);
  }
  return report;
}

[[noreturn]] void unstable_row(long i, double diagonal) {
  char text[640];
  std::snprintf(text, sizeof text,
                "row %ld of the implicit step has the diagonal %.3g: the step would amplify the "
                "value at point %ld instead of damping it (its Laplacian stencil's centre "
                "coefficient is positive and large: a sparse, one-sided neighbourhood; or the "
                "surface divergence of the velocity is below -1/dt: the surface is crushed "
                "there); refine the cloud there or lower the time step, and where the surface "
                "folds onto itself turn on self-contact (surface.contact.self)",
                i, diagonal, i);
  throw NumericalError({0.0, 0, "surface", i}, text);
}
}  // namespace

SparseSystem::SparseSystem() : solver_(std::make_unique<Solver>()) {
  solver_->with_ilu.preconditioner().setFillfactor(2);
  solver_->with_ilu.preconditioner().setDroptol(1e-3);
}
SparseSystem::~SparseSystem() = default;

LinearSolveReport SparseSystem::solve(const NeighbourLists& lists, const std::vector<double>& rhs,
                                      std::vector<double>& x, const LinearSolverOptions& options) {
  const long n = static_cast<long>(lists.points());
  auto& s = *solver_;
  s.triplets.clear();
  s.triplets.reserve(lists.index.size());
  for (long i = 0; i < n; ++i) {
    if (!(values[lists.begin(i)] > 0.0)) unstable_row(i, values[lists.begin(i)]);
    for (long k = lists.begin(i); k < lists.end(i); ++k)
      if (values[k] != 0.0) s.triplets.emplace_back(i, lists.index[k], values[k]);
  }
  s.matrix.resize(n, n);
  s.matrix.setFromTriplets(s.triplets.begin(), s.triplets.end());
  if (options.preconditioner == Preconditioner::jacobi)
    return run(s.with_diagonal, s.matrix, rhs, x, options);
  return run(s.with_ilu, s.matrix, rhs, x, options);
}

}  // namespace pellicle
