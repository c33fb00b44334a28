#include "pellicle/normals/isosurface.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <random>

#include "pellicle/normals/mirror_images.hpp"
#include "pellicle/normals/principal_directions.hpp"
#include "pellicle/pointcloud/cell_groups.hpp"

namespace pellicle {

namespace {

constexpr int kTries = 8;              //!< placements of the extra point before giving up
constexpr double kMaxCondition = 1e6;  //!< of A, i.e. 1e12 for the normal equations
//! Guarded variant: slopes |∇χ| × reach below which ∇χ is not used at all, and above which it
//! is used alone (a χ falling cleanly from 1 to 0 over the reach has about 1).
constexpr double kWeakSlope = 0.2, kSoundSlope = 0.8;

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
    // The 3^D B-splines centred on the cell centres around `cell`, as the polynomials they
    // are on the cell (also outside it: the χ = 2 point may lie there). f = ξ − ½ − (cell − 1)
    // lies in [½, 3⁄2) on the cell, where quadratic_bspline gives the same values.
    double w[D][3], dw[D][3];
    for (int d = 0; d < D; ++d) {
      const double f = (x[d] - origin[d]) / size - 0.5 - (cell[d] - 1);
      w[d][0] = 0.5 * (1.5 - f) * (1.5 - f);
      w[d][1] = 0.75 - (f - 1.0) * (f - 1.0);
      w[d][2] = 0.5 * (f - 0.5) * (f - 0.5);
      dw[d][0] = f - 1.5;
      dw[d][1] = -2.0 * (f - 1.0);
      dw[d][2] = f - 0.5;
    }
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

//! The side of a point relative to the fitted points: the sign of (x − mean) · ν, with ν their
//! direction of least spread.
template <int D>
struct PointsSide {
  Vec<D> mean, nu;
  explicit PointsSide(const std::vector<const Vec<D>*>& points) {
    mean = Vec<D>::Zero();
    for (const auto* x : points) mean += *x;
    mean /= static_cast<double>(points.size());
    nu = points.size() >= static_cast<std::size_t>(D) ? least_spread(points) : Vec<D>::Unit(D - 1);
  }
  double of(const Vec<D>& x) const { return (x - mean).dot(nu); }
};

//! The paper's χ = 2 experiment (§8): a second extra point, with χ = 2, so that 1 is not the
//! maximum of χ. The paper says only "random"; here it is the random χ = 0 point's mirror
//! image in the points' least-squares line (plane), so the two lie on opposite sides of the
//! points at the same distance and χ must rise through them (a χ = 2 point on the χ = 0
//! point's side would ask χ to fall and rise on the same side). It may lie outside the cell
//! or block: χ is the polynomial there (LocalBasis::evaluate).
template <int D>
Vec<D> chi_two_point(const std::vector<const Vec<D>*>& points, const Vec<D>& zero) {
  const PointsSide<D> side(points);
  return zero - 2.0 * side.of(zero) * side.nu;
}

//! A solved local χ.
struct ChiFit {
  Eigen::VectorXd chi;
  double condition = 0.0;  //!< cond(A)² of the system used
  //! Distance from the χ = 0 point(s) to the nearest fitted point: the length over which a
  //! sound χ falls from 1 to 0, so |∇χ| on the points is of order 1 / reach.
  double reach = 0.0;
};

template <int D>
double nearest_distance(const Vec<D>& x, const std::vector<const Vec<D>*>& points) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto* p : points) nearest = std::min(nearest, (*p - x).squaredNorm());
  return std::sqrt(nearest);
}

//! Extra points with their χ values, followed by their mirror images in `planes` (and in
//! every combination of them) with the same values.
template <int D>
std::vector<std::pair<Vec<D>, double>> with_images(std::vector<std::pair<Vec<D>, double>> extra,
                                                   const std::vector<MirrorPlane>& planes) {
  const std::size_t base = extra.size();
  for (int subset = 1; subset < (1 << planes.size()); ++subset) {
    for (std::size_t e = 0; e < base; ++e) {
      Vec<D> image = extra[e].first;
      for (std::size_t k = 0; k < planes.size(); ++k)
        if (subset & (1 << k))
          image[planes[k].axis] = 2.0 * planes[k].position - image[planes[k].axis];
      extra.push_back({image, extra[e].second});
    }
  }
  return extra;
}

//! The least-squares system: χ = 1 at the points, the given values at the extra points.
template <int D>
void chi_system(const LocalBasis<D>& basis, const std::vector<const Vec<D>*>& points,
                const std::vector<std::pair<Vec<D>, double>>& extra, Eigen::MatrixXd& A,
                Eigen::VectorXd& b) {
  const int m = basis.unknowns(), n = static_cast<int>(points.size());
  const int rows = n + static_cast<int>(extra.size());
  A.resize(rows, m);
  b.resize(rows);
  std::vector<double> row(m);
  for (int p = 0; p < rows; ++p) {
    basis.evaluate(p < n ? *points[p] : extra[p - n].first, row.data(), nullptr);
    for (int k = 0; k < m; ++k) A(p, k) = row[k];
    b[p] = p < n ? 1.0 : extra[p - n].second;
  }
}

//! Solve for χ (eq 10 in the least-squares sense) with the extra point moved until the
//! system is well conditioned. When the fitted points include their mirror images in
//! `planes`, so do the extra points, and χ is symmetric in the planes.
template <int D>
ChiFit solve_chi(const LocalBasis<D>& basis, const std::vector<const Vec<D>*>& points,
                 std::mt19937& rng, bool normal_equations, bool chi_two,
                 const std::vector<MirrorPlane>& planes,
                 const std::vector<Vec<D>>* fixed_extra = nullptr) {
  const int m = basis.unknowns();
  ChiFit fit;
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  if (fixed_extra) {  // the offset variant: no random point, no retries
    std::vector<std::pair<Vec<D>, double>> extra;
    fit.reach = std::numeric_limits<double>::infinity();
    for (const auto& x : *fixed_extra) {
      extra.push_back({x, 0.0});
      fit.reach = std::min(fit.reach, nearest_distance(x, points));
    }
    chi_system(basis, points, with_images(extra, planes), A, b);
    const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
    fit.chi = cod.solve(b);
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    const long rank = std::max<long>(1, qr.rank());
    const double condition =
        std::abs(qr.matrixQR()(0, 0)) / std::abs(qr.matrixQR()(rank - 1, rank - 1));
    fit.condition = condition * condition;
    return fit;
  }
  double best = std::numeric_limits<double>::infinity();
  for (int attempt = 0; attempt < kTries; ++attempt) {
    const Vec<D> zero = off_membrane_point(basis, points, rng);
    std::vector<std::pair<Vec<D>, double>> extra{{zero, 0.0}};
    if (chi_two) extra.push_back({chi_two_point(points, zero), 2.0});
    chi_system(basis, points, with_images(extra, planes), A, b);
    if (normal_equations) {  // thesis eqs 7.10–7.12: T χ = Sᵀ χ⁰
      const Eigen::MatrixXd T = A.transpose() * A;
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(T);
      const double condition =
          eig.eigenvalues().maxCoeff() / std::max(eig.eigenvalues().minCoeff(), 1e-300);
      if (condition < best) {
        best = condition;
        fit.chi = T.ldlt().solve(A.transpose() * b);
        fit.reach = nearest_distance(zero, points);
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
      fit.chi = rank == m
                    ? Eigen::VectorXd(qr.solve(b))
                    : Eigen::VectorXd(
                          Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(A).solve(b));
      fit.reach = nearest_distance(zero, points);
    }
    if (best < kMaxCondition) break;
  }
  fit.condition = normal_equations ? best : best * best;
  return fit;
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
                                       std::vector<Vec<D>>& normal,
                                       const std::vector<MirrorPlane>& planes) {
  const double h = setup_.cell;
  const CellGroups<D> groups(x, begin, end, setup_.grid_origin, h);
  statistics_ = {};
  statistics_.slope.assign(end - begin, 0.0);
  std::vector<std::vector<double>> conditions(groups.size());
  long fallbacks = 0;
#pragma omp parallel for schedule(dynamic, 16) reduction(+ : fallbacks)
  for (int g = 0; g < groups.size(); ++g) {
    const IVec<D> cell = groups.cell(g);
    auto gather = [&](const IVec<D>& lower, int s, std::vector<const Vec<D>*>& out) {
      groups.for_each_in_block(lower, s, [&](int other) {
        for (const long* p = groups.begin(other); p != groups.end(other); ++p)
          out.push_back(&x[*p]);
      });
    };
    // A cell with a face on a plane the membrane ends on (a grid line): its points' images lie
    // in the cell mirrored across it (and, at a corner, across two or three). A quadratic fit
    // takes them with the cell's points, and the extra points' images with the extra points,
    // so χ is symmetric in the plane and the end normal lies in it, as the connectivity
    // estimator's mirrored neighbour makes it; the end of the membrane is inside the data.
    // The hybrid rule counts the images with the cell's points when it chooses the quadratic.
    std::vector<MirrorPlane> imaged;
    for (const auto& m : planes) {
      const long plane = std::lround((m.position - setup_.grid_origin[m.axis]) / h);
      if (cell[m.axis] == plane || cell[m.axis] == plane - 1) imaged.push_back(m);
    }
    std::vector<int> image_cells;
    for (int subset = 1; subset < (1 << imaged.size()); ++subset) {
      IVec<D> image = cell;
      for (std::size_t k = 0; k < imaged.size(); ++k) {
        if (!(subset & (1 << k))) continue;
        const int axis = imaged[k].axis;
        const long plane = std::lround((imaged[k].position - setup_.grid_origin[axis]) / h);
        image[axis] = static_cast<int>(2 * plane - 1 - cell[axis]);
      }
      const int other = groups.find(image);
      if (other >= 0) image_cells.push_back(other);
    }
    auto cell_and_images = [&](std::vector<const Vec<D>*>& out) {
      for (const long* p = groups.begin(g); p != groups.end(g); ++p) out.push_back(&x[*p]);
      for (int other : image_cells)
        for (const long* p = groups.begin(other); p != groups.end(other); ++p)
          out.push_back(&x[*p]);
    };
    const long own = groups.count(g);
    long imaged_count = own;
    for (int other : image_cells) imaged_count += groups.count(other);
    LocalBasis<D> basis;
    std::vector<const Vec<D>*> fit;
    bool thin = false, thin_imaged = false;
    if (basis_ == IsosurfaceBasis::hybrid) {
      for (const long* p = groups.begin(g); p != groups.end(g); ++p) fit.push_back(&x[*p]);
      thin = !well_spread(fit, h);
      fit.clear();
      cell_and_images(fit);
      thin_imaged = !well_spread(fit, h);
      fit.clear();
    }
    const bool quadratic =
        basis_ == IsosurfaceBasis::quadratic ||
        (basis_ == IsosurfaceBasis::hybrid && imaged_count >= quadratic_threshold && !thin_imaged);
    if (quadratic) {
      basis = {true, setup_.grid_origin, h, cell};
      cell_and_images(fit);
    } else {
      // Linear on the cell, or (hybrid, too few points) on the smallest block of s^D cells
      // around it that holds enough points, the fullest such block. A single cell takes no
      // images: a bilinear χ even in the plane has no slope along it, so every normal of the
      // cell would be the plane's.
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
      // A joined block that straddles the plane evenly holds the images as points of its cells;
      // the extra points' images then keep χ symmetric. A single linear cell or an uneven
      // block takes no images.
      std::vector<MirrorPlane> even;
      for (const auto& m : imaged) {
        const long plane = std::lround((m.position - setup_.grid_origin[m.axis]) / h);
        if (s % 2 == 0 && lower[m.axis] + s / 2 == plane) even.push_back(m);
      }
      imaged = even;
    }
    std::mt19937 rng(setup_.seed ^ static_cast<unsigned>(CellGroups<D>::key(cell) * 2654435761u));
    ChiFit solved;
    if (offset_) {
      const auto extra = offset_points(basis, fit, h);
      solved = solve_chi(basis, fit, rng, false, false, imaged, &extra);
    } else {
      solved = solve_chi(basis, fit, rng, basis_ == IsosurfaceBasis::mass_matrix, chi_two_, imaged);
    }
    conditions[g].push_back(solved.condition);
    std::vector<double> value(basis.unknowns());
    std::vector<Vec<D>> grad(basis.unknowns());
    for (const long* p = groups.begin(g); p != groups.end(g); ++p) {
      basis.evaluate(x[*p], value.data(), grad.data());
      Vec<D> n = Vec<D>::Zero();
      for (int k = 0; k < basis.unknowns(); ++k) n += solved.chi[k] * grad[k];  // eqs 11, 16
      statistics_.slope[*p - begin] = n.norm() * solved.reach;
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
  frames(position, begin, end, normal, tangent,
         planes_ended_on<D>(position, begin, end, setup_.mirrors, setup_.cell));
}

template <int D>
int IsosurfaceEstimator<D>::reach() const {
  // A cell's fit takes the points of its cell and their images beyond the planes it touches
  // (0), or, with the hybrid rule, those of the block of up to 4^D cells it joins, within 3
  // cells of it, and their images, which are images of points within 3 cells too. The guarded
  // variant's neighbourhood radius follows the whole body's point spacing.
  if (guarded_) return -1;
  return basis_ == IsosurfaceBasis::hybrid ? 3 : 0;
}

template <int D>
unsigned IsosurfaceEstimator<D>::planes_touched(const std::vector<Vec<D>>& position, long begin,
                                                long end) const {
  return mirrors_touched<D>(position, begin, end, setup_.mirrors, setup_.cell);
}

template <int D>
bool IsosurfaceEstimator<D>::estimate_part(const BodyPart& part,
                                           const std::vector<Vec<D>>& position,
                                           std::vector<Vec<D>>& normal,
                                           std::vector<Vec<D>>& tangent) {
  if (reach() < 0) return false;
  frames(position, 0, static_cast<long>(position.size()), normal, tangent,
         planes_ended_on(part.planes, setup_.mirrors));
  return true;
}

template <int D>
void IsosurfaceEstimator<D>::frames(const std::vector<Vec<D>>& position, long begin, long end,
                                    std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent,
                                    const std::vector<MirrorPlane>& ended_on) {
  const std::vector<Vec<D>> previous(normal.begin() + begin, normal.begin() + end);
  // The fits see the points' mirror images beyond the symmetry planes the membrane ends on
  // (mirror_images.hpp); two cells cover every block a cell next to a plane can join.
  const std::vector<Vec<D>> cloud =
      with_images_in<D>(position, begin, end, ended_on, setup_.cell, 2.0 * setup_.cell);
  const long n = end - begin;
  std::vector<Vec<D>> raw(cloud.size(), Vec<D>::Zero());
  gradients(cloud, 0, static_cast<long>(cloud.size()), raw, ended_on);
  if (guarded_) {
    // Where χ has too little slope across the points for its gradient to mean anything (its
    // maximum is about 1 on them: paper §8), the neighbours' direction of least spread.
    const PrincipalDirections<D> directions(cloud, setup_.cell);
    long guarded = 0;
#pragma omp parallel for schedule(static) reduction(+ : guarded)
    for (long p = 0; p < n; ++p) {
      const double w =
          std::clamp((statistics_.slope[p] - kWeakSlope) / (kSoundSlope - kWeakSlope), 0.0, 1.0);
      if (w >= 1.0) continue;
      ++guarded;
      Vec<D> across = directions.least_spread(p);
      if (across.dot(raw[p]) < 0.0) across = -across;
      raw[p] = (w * raw[p] + (1.0 - w) * across).normalized();
    }
    statistics_.guarded = guarded;
  }
  std::copy(raw.begin(), raw.begin() + n, normal.begin() + begin);
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
  return std::make_unique<IsosurfaceEstimator<D>>(setup, IsosurfaceBasis::hybrid,
                                                  IsosurfaceOptions{true, false, false});
}
template <int D>
std::unique_ptr<FrameEstimator<D>> make_isosurface_chi_two(const FrameSetup<D>& setup) {
  return std::make_unique<IsosurfaceEstimator<D>>(setup, IsosurfaceBasis::hybrid,
                                                  IsosurfaceOptions{false, true, false});
}
template <int D>
std::unique_ptr<FrameEstimator<D>> make_isosurface_guarded(const FrameSetup<D>& setup) {
  return std::make_unique<IsosurfaceEstimator<D>>(setup, IsosurfaceBasis::hybrid,
                                                  IsosurfaceOptions{false, false, true});
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
template std::unique_ptr<FrameEstimator<2>> make_isosurface_chi_two<2>(const FrameSetup<2>&);
template std::unique_ptr<FrameEstimator<3>> make_isosurface_chi_two<3>(const FrameSetup<3>&);
template std::unique_ptr<FrameEstimator<2>> make_isosurface_guarded<2>(const FrameSetup<2>&);
template std::unique_ptr<FrameEstimator<3>> make_isosurface_guarded<3>(const FrameSetup<3>&);
template std::unique_ptr<FrameEstimator<2>> make_mass_matrix<2>(const FrameSetup<2>&);
template std::unique_ptr<FrameEstimator<3>> make_mass_matrix<3>(const FrameSetup<3>&);

}  // namespace pellicle
