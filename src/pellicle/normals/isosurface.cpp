#include "pellicle/normals/isosurface.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <random>

#include "pellicle/core/bspline.hpp"
#include "pellicle/normals/cell_groups.hpp"

namespace pellicle {

namespace {

constexpr int kTries = 8;              //!< placements of the extra point before giving up
constexpr double kMaxCondition = 1e6;  //!< of A, i.e. 1e12 for the normal equations

//! The local interpolant: linear on a block of s^D cells (its 2^D corners), or quadratic
//! B-splines on the 3^D cell centres around one cell.
template <int D>
struct LocalBasis {
  bool quadratic = false;
  Vec<D> origin;  //!< linear: the block's lower corner; quadratic: the grid origin
  double size;    //!< linear: block edge s h; quadratic: the cell h
  IVec<D> cell;   //!< quadratic: the cell whose points are fitted

  int unknowns() const { return quadratic ? (D == 2 ? 9 : 27) : (1 << D); }

  //! Values (and, if grad is non-null, gradients) of every basis function at x.
  void evaluate(const Vec<D>& x, double* value, Vec<D>* grad) const {
    if (!quadratic) {
      const Vec<D> xi = (x - origin) / size;
      for (int c = 0; c < (1 << D); ++c) {
        double v = 1.0;
        Vec<D> g = Vec<D>::Constant(1.0 / size);
        for (int d = 0; d < D; ++d) {
          const bool upper = c & (1 << d);
          const double f = upper ? xi[d] : 1.0 - xi[d];
          v *= f;
          for (int e = 0; e < D; ++e) g[e] *= e == d ? (upper ? 1.0 : -1.0) : f;
        }
        value[c] = v;
        if (grad) grad[c] = g;
      }
      return;
    }
    double w[D][3], dw[D][3];
    for (int d = 0; d < D; ++d)  // cell centres sit at integer values of ξ − ½
      quadratic_bspline((x[d] - origin[d]) / size - 0.5, w[d], dw[d]);
    for (int k = 0; k < unknowns(); ++k) {
      int rest = k;
      double v = 1.0;
      Vec<D> g = Vec<D>::Constant(1.0 / size);
      for (int d = 0; d < D; ++d) {
        const int a = rest % 3;
        rest /= 3;
        v *= w[d][a];
        for (int e = 0; e < D; ++e) g[e] *= e == d ? dw[d][a] : w[d][a];
      }
      value[k] = v;
      if (grad) grad[k] = g;
    }
  }

  //! A point drawn uniformly in the region the construction covers.
  Vec<D> random_point(std::mt19937& rng) const {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Vec<D> x;
    for (int d = 0; d < D; ++d)
      x[d] = quadratic ? origin[d] + (cell[d] + u(rng)) * size : origin[d] + u(rng) * size;
    return x;
  }
};

//! The extra point with χ = 0 must lie off the membrane: of a few random candidates in the
//! cell, the one farthest from every membrane point (a point next to the membrane would
//! force χ from 1 to 0 over a tiny distance and tilt ∇χ).
template <int D>
Vec<D> off_membrane_point(const LocalBasis<D>& basis, const std::vector<const Vec<D>*>& points,
                          std::mt19937& rng) {
  constexpr int kCandidates = 16;
  Vec<D> best = basis.random_point(rng);
  double farthest = -1.0;
  for (int c = 0; c < kCandidates; ++c) {
    const Vec<D> x = c == 0 ? best : basis.random_point(rng);
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto* p : points) nearest = std::min(nearest, (*p - x).squaredNorm());
    if (nearest > farthest) farthest = nearest, best = x;
  }
  return best;
}

//! Principal direction of least spread of the points: the fallback normal.
template <int D>
Vec<D> least_spread(const std::vector<const Vec<D>*>& points) {
  Vec<D> mean = Vec<D>::Zero();
  for (const auto* x : points) mean += *x;
  mean /= static_cast<double>(points.size());
  Mat<D> cov = Mat<D>::Zero();
  for (const auto* x : points) cov += (*x - mean) * (*x - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Mat<D>> eig(cov);
  return eig.eigenvectors().col(0);
}

//! The offset variant's extra points: 2^(D−1) points with χ = 0 on one side of the points,
//! half a cell along their direction of least spread and a quarter cell apart across it,
//! kept inside the region the basis covers. They pin χ's slope across the whole patch, which
//! a single point cannot in 3D (trilinear functions vanishing on a plane form a 4-dimensional
//! family), so ∇χ cannot vanish or turn along the patch.
template <int D>
std::vector<Vec<D>> offset_points(const LocalBasis<D>& basis,
                                  const std::vector<const Vec<D>*>& points, double cell) {
  Vec<D> mean = Vec<D>::Zero();
  for (const auto* x : points) mean += *x;
  mean /= static_cast<double>(points.size());
  const Vec<D> nu =
      points.size() >= static_cast<std::size_t>(D) ? least_spread(points) : Vec<D>::Unit(D - 1);
  Mat<D> frame =
      Eigen::JacobiSVD<Mat<D>>(Mat<D>(nu * nu.transpose()), Eigen::ComputeFullU).matrixU();
  Vec<D> lo, hi;
  for (int d = 0; d < D; ++d) {
    lo[d] = basis.quadratic ? basis.origin[d] + basis.cell[d] * basis.size : basis.origin[d];
    hi[d] = lo[d] + basis.size;
  }
  std::vector<Vec<D>> out;
  for (int k = 0; k < (1 << (D - 1)); ++k) {
    Vec<D> x = mean + 0.5 * cell * nu;
    for (int d = 1; d < D; ++d) x += ((k >> (d - 1)) & 1 ? 0.25 : -0.25) * cell * frame.col(d);
    out.push_back(x.cwiseMax(lo).cwiseMin(hi));
  }
  return out;
}

//! Solve for χ (eq 10 in the least-squares sense) with the extra point moved until the
//! system is well conditioned. Returns cond(A)² of the system used.
template <int D>
double solve_chi(const LocalBasis<D>& basis, const std::vector<const Vec<D>*>& points,
                 std::mt19937& rng, bool normal_equations, Eigen::VectorXd& chi,
                 const std::vector<Vec<D>>* fixed_extra = nullptr) {
  const int m = basis.unknowns(), n = static_cast<int>(points.size());
  if (fixed_extra) {  // the offset variant: no random point, no retries
    const int e = static_cast<int>(fixed_extra->size());
    Eigen::MatrixXd A(n + e, m);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n + e);
    b.head(n).setOnes();
    std::vector<double> row(m);
    for (int p = 0; p < n + e; ++p) {
      basis.evaluate(p < n ? *points[p] : (*fixed_extra)[p - n], row.data(), nullptr);
      for (int k = 0; k < m; ++k) A(p, k) = row[k];
    }
    const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
    chi = cod.solve(b);
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    const long rank = std::max<long>(1, qr.rank());
    const double condition =
        std::abs(qr.matrixQR()(0, 0)) / std::abs(qr.matrixQR()(rank - 1, rank - 1));
    return condition * condition;
  }
  Eigen::MatrixXd A(n + 1, m);
  Eigen::VectorXd b = Eigen::VectorXd::Ones(n + 1);
  b[n] = 0.0;
  std::vector<double> row(m);
  for (int p = 0; p < n; ++p) {
    basis.evaluate(*points[p], row.data(), nullptr);
    for (int k = 0; k < m; ++k) A(p, k) = row[k];
  }
  double best = std::numeric_limits<double>::infinity();
  for (int attempt = 0; attempt < kTries; ++attempt) {
    basis.evaluate(off_membrane_point(basis, points, rng), row.data(), nullptr);
    for (int k = 0; k < m; ++k) A(n, k) = row[k];
    if (normal_equations) {  // thesis eqs 7.10–7.12: T χ = Sᵀ χ⁰
      const Eigen::MatrixXd T = A.transpose() * A;
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(T);
      const double condition =
          eig.eigenvalues().maxCoeff() / std::max(eig.eigenvalues().minCoeff(), 1e-300);
      if (condition < best) {
        best = condition;
        chi = T.ldlt().solve(A.transpose() * b);
      }
      if (best < kMaxCondition * kMaxCondition) break;
      continue;
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    const long rank = qr.rank();
    if (rank == 0) continue;
    const auto R = qr.matrixQR();
    const double condition = std::abs(R(0, 0)) / std::abs(R(rank - 1, rank - 1));
    if (condition < best) {
      best = condition;
      chi = rank == m ? Eigen::VectorXd(qr.solve(b))
                      : Eigen::VectorXd(
                            Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(A).solve(b));
    }
    if (best < kMaxCondition) break;
  }
  return normal_equations ? best : best * best;
}

//! Whether points span a piece of curve (2D) or surface (3D) wide enough to fix a normal:
//! a cell that the membrane only grazes holds a few points along a sliver (3D: nearly on a
//! line), whose normal no local fit can tell. Spread measured by the covariance eigenvalues.
template <int D>
bool well_spread(const std::vector<const Vec<D>*>& points, double h) {
  if (points.size() < static_cast<std::size_t>(D)) return false;
  Vec<D> mean = Vec<D>::Zero();
  for (const auto* x : points) mean += *x;
  mean /= static_cast<double>(points.size());
  Mat<D> cov = Mat<D>::Zero();
  for (const auto* x : points) cov += (*x - mean) * (*x - mean).transpose();
  cov /= static_cast<double>(points.size());
  const auto eigenvalues = Eigen::SelfAdjointEigenSolver<Mat<D>>(cov).eigenvalues();
  return eigenvalues[1] >= 0.01 * h * h;  // 2D: along the curve; 3D: the narrower in-plane spread
}

}  // namespace

template <int D>
void IsosurfaceEstimator<D>::gradients(const std::vector<Vec<D>>& x, long begin, long end,
                                       std::vector<Vec<D>>& normal) {
  const double h = setup_.cell;
  const CellGroups<D> groups(x, begin, end, setup_.grid_origin, h);
  statistics_ = {};
  std::vector<std::vector<double>> conditions(groups.size());
  long fallbacks = 0;
#pragma omp parallel for schedule(dynamic, 16) reduction(+ : fallbacks)
  for (int g = 0; g < groups.size(); ++g) {
    const IVec<D> cell = groups.cell(g);
    const long own = groups.count(g);
    auto gather = [&](const IVec<D>& lower, int s, std::vector<const Vec<D>*>& out) {
      groups.for_each_in_block(lower, s, [&](int other) {
        for (const long* p = groups.begin(other); p != groups.end(other); ++p)
          out.push_back(&x[*p]);
      });
    };
    LocalBasis<D> basis;
    std::vector<const Vec<D>*> fit;
    bool thin = false;
    if (basis_ == IsosurfaceBasis::hybrid) {
      for (const long* p = groups.begin(g); p != groups.end(g); ++p) fit.push_back(&x[*p]);
      thin = !well_spread(fit, h);
      fit.clear();
    }
    const bool quadratic =
        basis_ == IsosurfaceBasis::quadratic ||
        (basis_ == IsosurfaceBasis::hybrid && own >= quadratic_threshold && !thin);
    if (quadratic) {
      basis = {true, setup_.grid_origin, h, cell};
      for (const long* p = groups.begin(g); p != groups.end(g); ++p) fit.push_back(&x[*p]);
    } else {
      // Linear on the cell, or (hybrid, too few points) on the smallest block of s^D cells
      // around it that holds enough points, the fullest such block.
      int s = 1;
      IVec<D> lower = cell;
      if (basis_ == IsosurfaceBasis::hybrid && (own < linear_threshold || thin)) {
        for (s = 2; s <= 4; ++s) {
          long best = -1;
          IVec<D> offset = IVec<D>::Zero();
          for (int o = 0; o < static_cast<int>(std::pow(s, D)); ++o) {
            int rest = o;
            for (int d = 0; d < D; ++d) offset[d] = rest % s, rest /= s;
            long count = 0;
            groups.for_each_in_block(cell - offset, s,
                                     [&](int other) { count += groups.count(other); });
            if (count > best) best = count, lower = cell - offset;
          }
          std::vector<const Vec<D>*> block;
          gather(lower, s, block);
          if (best >= linear_threshold && well_spread(block, h)) break;
        }
        s = std::min(s, 4);
      }
      basis = {false, setup_.grid_origin + h * lower.template cast<double>(), s * h, lower};
      gather(lower, s, fit);
    }
    std::mt19937 rng(setup_.seed ^ static_cast<unsigned>(CellGroups<D>::key(cell) * 2654435761u));
    Eigen::VectorXd chi;
    if (offset_) {
      const auto extra = offset_points(basis, fit, h);
      conditions[g].push_back(solve_chi(basis, fit, rng, false, chi, &extra));
    } else {
      conditions[g].push_back(
          solve_chi(basis, fit, rng, basis_ == IsosurfaceBasis::mass_matrix, chi));
    }
    std::vector<double> value(basis.unknowns());
    std::vector<Vec<D>> grad(basis.unknowns());
    for (const long* p = groups.begin(g); p != groups.end(g); ++p) {
      basis.evaluate(x[*p], value.data(), grad.data());
      Vec<D> n = Vec<D>::Zero();
      for (int k = 0; k < basis.unknowns(); ++k) n += chi[k] * grad[k];  // eqs 11, 16
      if (n.norm() > 1e-9 / h && n.allFinite()) {
        normal[*p] = n.normalized();
      } else {
        ++fallbacks;
        normal[*p] =
            fit.size() >= static_cast<std::size_t>(D) ? least_spread(fit) : Vec<D>::Unit(D - 1);
      }
    }
  }
  statistics_.fallbacks = fallbacks;
  for (const auto& c : conditions)
    statistics_.condition.insert(statistics_.condition.end(), c.begin(), c.end());
}

template <int D>
void IsosurfaceEstimator<D>::estimate(const std::vector<Vec<D>>& position, long begin, long end,
                                      std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) {
  const std::vector<Vec<D>> previous(normal.begin() + begin, normal.begin() + end);
  gradients(position, begin, end, normal);
  std::vector<Vec<D>> previous_full(normal.size(), Vec<D>::Zero());
  std::copy(previous.begin(), previous.end(), previous_full.begin() + begin);
  complete_frames<D>(position, begin, end, setup_.orientation, previous_full, normal, tangent,
                     setup_.cell);
}

template <int D>
std::unique_ptr<FrameEstimator<D>> make_isosurface_linear(const FrameSetup<D>& setup) {
  return std::make_unique<IsosurfaceEstimator<D>>(setup, IsosurfaceBasis::linear);
}
template <int D>
std::unique_ptr<FrameEstimator<D>> make_isosurface_quadratic(const FrameSetup<D>& setup) {
  return std::make_unique<IsosurfaceEstimator<D>>(setup, IsosurfaceBasis::quadratic);
}
template <int D>
std::unique_ptr<FrameEstimator<D>> make_isosurface_hybrid(const FrameSetup<D>& setup) {
  return std::make_unique<IsosurfaceEstimator<D>>(setup, IsosurfaceBasis::hybrid);
}
template <int D>
std::unique_ptr<FrameEstimator<D>> make_isosurface_offset(const FrameSetup<D>& setup) {
  return std::make_unique<IsosurfaceEstimator<D>>(setup, IsosurfaceBasis::hybrid, true);
}
template <int D>
std::unique_ptr<FrameEstimator<D>> make_mass_matrix(const FrameSetup<D>& setup) {
  return std::make_unique<IsosurfaceEstimator<D>>(setup, IsosurfaceBasis::mass_matrix);
}

template class IsosurfaceEstimator<2>;
template class IsosurfaceEstimator<3>;
template std::unique_ptr<FrameEstimator<2>> make_isosurface_linear<2>(const FrameSetup<2>&);
template std::unique_ptr<FrameEstimator<3>> make_isosurface_linear<3>(const FrameSetup<3>&);
template std::unique_ptr<FrameEstimator<2>> make_isosurface_quadratic<2>(const FrameSetup<2>&);
template std::unique_ptr<FrameEstimator<3>> make_isosurface_quadratic<3>(const FrameSetup<3>&);
template std::unique_ptr<FrameEstimator<2>> make_isosurface_hybrid<2>(const FrameSetup<2>&);
template std::unique_ptr<FrameEstimator<3>> make_isosurface_hybrid<3>(const FrameSetup<3>&);
template std::unique_ptr<FrameEstimator<2>> make_isosurface_offset<2>(const FrameSetup<2>&);
template std::unique_ptr<FrameEstimator<3>> make_isosurface_offset<3>(const FrameSetup<3>&);
template std::unique_ptr<FrameEstimator<2>> make_mass_matrix<2>(const FrameSetup<2>&);
template std::unique_ptr<FrameEstimator<3>> make_mass_matrix<3>(const FrameSetup<3>&);

}  // namespace pellicle
