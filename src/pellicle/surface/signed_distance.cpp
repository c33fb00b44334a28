#include "pellicle/surface/signed_distance.hpp"

#include <Eigen/Geometry>
#include <Eigen/QR>

#include <cmath>

namespace pellicle {

namespace {

//! The terms of eq 10 in the local coordinates q = (u, [v], w), with their gradient.
template <int D>
int terms(const Vec<D>& q, bool quadratic, double* value, Vec<D>* gradient) {
  int k = 0;
  auto term = [&](double f, const Vec<D>& g) {
    value[k] = f;
    if (gradient) gradient[k] = g;
    ++k;
  };
  const Vec<D> zero = Vec<D>::Zero();
  const Vec<D> e_u = Vec<D>::Unit(0), e_w = Vec<D>::Unit(D - 1);
  term(1.0, zero);
  term(q[0], e_u);
  if constexpr (D == 3) term(q[1], Vec<D>::Unit(1));
  if (quadratic) {
    term(q[0] * q[0], 2.0 * q[0] * e_u);
    if constexpr (D == 3) {
      term(q[1] * q[1], 2.0 * q[1] * Vec<D>::Unit(1));
      term(q[0] * q[1], q[1] * e_u + q[0] * Vec<D>::Unit(1));
    }
  }
  term(q[D - 1], e_w);
  return k;
}

}  // namespace

template <int D>
SignedDistance<D> signed_distance(const Vec<D>& x, const Vec<D>* points, const Vec<D>* normals,
                                  int count, double xi) {
  SignedDistance<D> out;
  if (count < 1 || !(xi > 0.0)) return out;
  // The frame: w along the mean normal, u (and v) across it; origin at the nearest point.
  Vec<D> w = Vec<D>::Zero();
  for (int m = 0; m < count; ++m) w += normals[m];
  if (!(w.norm() > 1e-12)) return out;
  w.normalize();
  Mat<D> frame;  // columns u, (v,) w
  if constexpr (D == 3) {
    const Vec3 a = std::abs(w[0]) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    const Vec3 u = w.cross(a).normalized();
    frame << u, w.cross(u), w;
  } else {
    frame << Vec2(-w[1], w[0]), w;
  }
  const Vec<D> origin = points[0];
  // Lengths in units of the patch's size, for the conditioning of the fit.
  double size = xi;
  for (int m = 0; m < count; ++m) size = std::max(size, (points[m] - origin).norm());
  auto local = [&](const Vec<D>& y) -> Vec<D> { return frame.transpose() * (y - origin) / size; };

  constexpr int kQuadraticPoints = D == 3 ? 6 : 3;
  const bool quadratic = count >= kQuadraticPoints;
  double row[7];
  const int unknowns = terms<D>(Vec<D>::Zero(), quadratic, row, nullptr);
  Eigen::MatrixXd a(3 * count, unknowns);
  Eigen::VectorXd b(3 * count);
  for (int m = 0; m < count; ++m)
    for (int s = -1; s <= 1; ++s) {  // d(x_m + s ξ n_m) = s ξ
      const int r = 3 * m + s + 1;
      terms<D>(local(points[m] + s * xi * normals[m]), quadratic, row, nullptr);
      for (int k = 0; k < unknowns; ++k) a(r, k) = row[k];
      b[r] = s * xi / size;
    }
  // The minimum-norm least-squares solution: with one or two points the plane's tilt is not
  // fixed by the conditions and is taken as none. The entries are of order 1 (lengths in
  // units of the patch), so directions below 1e-10 of the largest are rounding noise (a
  // tangent column holds ±1e-17 where the normals are the frame's w) and count as none.
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> fit(a.rows(), a.cols());
  fit.setThreshold(1e-10);
  fit.compute(a);
  const Eigen::VectorXd c = fit.solve(b);
  Vec<D> gradient_terms[7];
  terms<D>(local(x), quadratic, row, gradient_terms);
  double d = 0.0;
  Vec<D> g = Vec<D>::Zero();
  for (int k = 0; k < unknowns; ++k) {
    d += c[k] * row[k];
    g += c[k] * gradient_terms[k];
  }
  const double slope = g.norm();  // |∇d| in local units: d is in units of size too
  if (!(slope > 1e-6) || !std::isfinite(d)) return out;
  out.distance = d / slope * size;
  out.direction = frame * (g / slope);
  out.valid = true;
  return out;
}

template SignedDistance<2> signed_distance<2>(const Vec2&, const Vec2*, const Vec2*, int, double);
template SignedDistance<3> signed_distance<3>(const Vec3&, const Vec3*, const Vec3*, int, double);

}  // namespace pellicle
