// Axis-aligned ellipses and ellipsoids with exact closest points.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "pellicle/geometry/shape_support.hpp"
#include "pellicle/geometry/surface_shapes.hpp"

namespace pellicle {
namespace {

template <int D>
class EllipsoidShape final : public SurfaceShape<D> {
 public:
  EllipsoidShape(const Vec<D>& center, const Vec<D>& semi_axes)
      : center_(center), axes_(semi_axes) {
    if constexpr (D == 3) {
      carrier_ = carrier_of(make_ellipsoid(center, semi_axes, 0.3 * semi_axes.maxCoeff()));
    } else {
      carrier_ = closed_polygon(
          [&](double u) {
            const double t = 2 * std::numbers::pi * u;
            return Vec2(center + semi_axes.cwiseProduct(Vec2(std::cos(t), std::sin(t))));
          },
          256);
    }
  }

  std::string describe() const override {
    return std::string(D == 3 ? "ellipsoid" : "ellipse") + " with semi-axes " +
           describe_vector<D>(axes_) + " about " + describe_vector<D>(center_);
  }

  //! The closest point solves y_d = a_d² x_d / (t + a_d²) with Σ (y_d / a_d)² = 1 for the
  //! Lagrange multiplier t (Eberly, "Distance from a point to an ellipse, an ellipsoid, or a
  //! hyperellipsoid"), worked in the positive orthant, where the root is unique.
  Vec<D> project(const Vec<D>& x) const override {
    const Vec<D> q = x - center_;
    const Vec<D> y = q.cwiseAbs();
    const Vec<D> a2 = axes_.cwiseProduct(axes_);
    int smallest = 0;
    for (int d = 1; d < D; ++d)
      if (axes_[d] < axes_[smallest]) smallest = d;
    Vec<D> foot = Vec<D>::Zero();
    if (y[smallest] == 0.0) {
      // On the plane of the shortest axis, inside the evolute, the nearest point leaves the
      // plane: t = −a_min².
      double sum = 0.0;
      for (int d = 0; d < D; ++d)
        if (d != smallest && a2[d] > a2[smallest]) {
          foot[d] = a2[d] * y[d] / (a2[d] - a2[smallest]);
          sum += foot[d] * foot[d] / a2[d];
        }
      bool degenerate = sum < 1.0;
      for (int d = 0; d < D; ++d)
        degenerate = degenerate && (d == smallest || a2[d] > a2[smallest] || y[d] == 0.0);
      if (degenerate) {
        foot[smallest] = axes_[smallest] * std::sqrt(1.0 - sum);
        return restore(foot, q);
      }
    }
    double lowest = 1e308;  // t > −min a_d² over the components that are not zero
    double reach = 0.0;
    for (int d = 0; d < D; ++d)
      if (y[d] > 0.0) lowest = std::min(lowest, a2[d]), reach += a2[d] * y[d] * y[d];
    if (reach == 0.0) {  // the centre: every vertex of the shortest axis is nearest
      foot[smallest] = axes_[smallest];
      return center_ + foot;
    }
    auto g = [&](double t) {
      double sum = -1.0;
      for (int d = 0; d < D; ++d)
        if (y[d] > 0.0) sum += a2[d] * y[d] * y[d] / ((t + a2[d]) * (t + a2[d]));
      return sum;
    };
    // Safeguarded Newton: g is convex and decreasing on (lo, ∞); bisect when a step leaves
    // the bracket.
    double lo = -lowest, hi = std::sqrt(reach);  // g(lo⁺) = +∞, g(hi) ≤ 0
    double t = g(0.0) > 0.0 ? 0.5 * hi : -0.5 * lowest;
    const double scale = a2.maxCoeff();
    for (int iteration = 0; iteration < 100; ++iteration) {
      const double value = g(t);
      if (value == 0.0) break;
      (value > 0.0 ? lo : hi) = t;
      double slope = 0.0;
      for (int d = 0; d < D; ++d)
        if (y[d] > 0.0) slope -= 2.0 * a2[d] * y[d] * y[d] / std::pow(t + a2[d], 3);
      const double newton = t - value / slope;
      const double next = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
      const bool converged = std::abs(next - t) <= 1e-15 * (std::abs(t) + scale);
      t = next;
      if (converged) break;
    }
    for (int d = 0; d < D; ++d) foot[d] = a2[d] * y[d] / (t + a2[d]);
    return restore(foot, q);
  }

  Vec<D> normal(const Vec<D>& x) const override {
    const Vec<D> p = project(x) - center_;
    return p.cwiseQuotient(axes_.cwiseProduct(axes_)).normalized();
  }

  double surface_error(const Vec<D>& x) const override { return (x - project(x)).norm(); }

  //! Ramanujan's second approximation of the perimeter (relative error below 4·10⁻⁴ at
  //! any aspect ratio) and Thomsen's of the area (below 1.1 %).
  double measure() const override {
    constexpr double pi = std::numbers::pi;
    if constexpr (D == 2) {
      const double a = axes_[0], b = axes_[1], h = (a - b) * (a - b) / ((a + b) * (a + b));
      return pi * (a + b) * (1.0 + 3.0 * h / (10.0 + std::sqrt(4.0 - 3.0 * h)));
    } else {
      constexpr double p = 1.6075;
      const double a = std::pow(axes_[0], p), b = std::pow(axes_[1], p), c = std::pow(axes_[2], p);
      return 4.0 * pi * std::pow((a * b + a * c + b * c) / 3.0, 1.0 / p);
    }
  }

  PointSample<D> sample(const SamplingOptions& options) const override {
    return sample_closed<D>(*this, carrier_, options);
  }

 private:
  //! The foot point in the orthant of q, from its mirror image in the positive one.
  Vec<D> restore(const Vec<D>& foot, const Vec<D>& q) const {
    Vec<D> p;
    for (int d = 0; d < D; ++d) p[d] = q[d] < 0.0 ? -foot[d] : foot[d];
    return center_ + p;
  }

  Vec<D> center_, axes_;
  std::vector<Simplex<D>> carrier_;
};

}  // namespace

template <int D>
SurfaceShapePtr<D> make_ellipsoid_shape(const Vec<D>& center, const Vec<D>& semi_axes) {
  return std::make_unique<EllipsoidShape<D>>(center, semi_axes);
}

template SurfaceShapePtr<2> make_ellipsoid_shape<2>(const Vec2&, const Vec2&);
template SurfaceShapePtr<3> make_ellipsoid_shape<3>(const Vec3&, const Vec3&);

}  // namespace pellicle
