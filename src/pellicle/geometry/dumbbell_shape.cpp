// The dumbbell of Suchde & Kuhnert §4.2.3 (Fig. 14): two balls of radius R with centres
// `separation` apart on a line along x, joined by a rod of radius r along that line, the
// boundary of their union (a sharp crease where rod and balls meet). Described by the
// signed distance f = min(f_ball1, f_ball2, f_rod), exact outside; the carrier comes from
// marching simplices on a grid and candidates reach f = 0 by steps along ∇f.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "pellicle/geometry/shape_support.hpp"
#include "pellicle/geometry/surface_shapes.hpp"

namespace pellicle {
namespace {

template <int D>
class Dumbbell final : public SurfaceShape<D> {
 public:
  Dumbbell(const Vec<D>& center, double ball_radius, double separation, double rod_radius)
      : center_(center), ball_(ball_radius), half_(0.5 * separation), rod_(rod_radius) {
    // Cells a third of the rod's radius (the thinnest feature), at most about 4·10⁶ nodes.
    Vec<D> extent = Vec<D>::Constant(2.0 * ball_);
    extent[0] += 2.0 * half_;
    double cell = rod_ / 3.0;
    cell = std::max(cell, std::pow(extent.prod() / 4e6, 1.0 / D));
    const Vec<D> margin = Vec<D>::Constant(2.0 * cell);
    carrier_ =
        zero_level_set<D>([this](const Vec<D>& x) { return value(x); },
                          center_ - 0.5 * extent - margin, center_ + 0.5 * extent + margin, cell);
  }

  std::string describe() const override {
    return "dumbbell: balls of radius " + describe_number(ball_) + " with centres " +
           describe_number(2.0 * half_) + " apart along x about " + describe_vector<D>(center_) +
           ", joined by a rod of radius " + describe_number(rod_);
  }

  //! Steps x ← x − f ∇f (|∇f| = 1 for a distance) until they are below 10⁻¹⁴ of the size.
  Vec<D> project(const Vec<D>& x) const override {
    Vec<D> y = x;
    for (int iteration = 0; iteration < 100; ++iteration) {
      const Vec<D> step = value(y) * gradient(y);
      y -= step;
      if (step.norm() <= 1e-14 * ball_) break;
    }
    return y;
  }

  Vec<D> normal(const Vec<D>& x) const override { return gradient(project(x)); }

  double surface_error(const Vec<D>& x) const override { return std::abs(value(x)); }

  double measure() const override { return carrier_measure<D>(carrier_); }

  PointSample<D> sample(const SamplingOptions& options) const override {
    return sample_closed<D>(*this, carrier_, options);
  }

 private:
  //! Signed distance to a ball about the centre offset by s along x.
  double ball(const Vec<D>& x, double s) const {
    Vec<D> c = center_;
    c[0] += s;
    return (x - c).norm() - ball_;
  }
  //! Signed distance to the rod, a cylinder of radius r from −half to +half along x.
  double rod(const Vec<D>& x) const {
    const Vec<D> d = x - center_;
    const double along = std::abs(d[0]) - half_;
    const double across = d.template tail<D - 1>().norm() - rod_;
    const double outside = std::hypot(std::max(along, 0.0), std::max(across, 0.0));
    return outside + std::min(std::max(along, across), 0.0);
  }
  double value(const Vec<D>& x) const {
    return std::min({ball(x, -half_), ball(x, half_), rod(x)});
  }
  //! ∇f by central differences (f is a distance: |∇f| = 1 off the crease).
  Vec<D> gradient(const Vec<D>& x) const {
    const double e = 1e-7 * ball_;
    Vec<D> g;
    for (int d = 0; d < D; ++d) {
      Vec<D> a = x, b = x;
      a[d] += e;
      b[d] -= e;
      g[d] = (value(a) - value(b)) / (2.0 * e);
    }
    const double norm = g.norm();
    return norm > 0.0 ? Vec<D>(g / norm) : Vec<D>(Vec<D>::UnitX());
  }

  Vec<D> center_;
  double ball_, half_, rod_;
  std::vector<Simplex<D>> carrier_;
};

}  // namespace

template <int D>
SurfaceShapePtr<D> make_dumbbell_shape(const Vec<D>& center, double ball_radius, double separation,
                                       double rod_radius) {
  return std::make_unique<Dumbbell<D>>(center, ball_radius, separation, rod_radius);
}

template SurfaceShapePtr<2> make_dumbbell_shape<2>(const Vec2&, double, double, double);
template SurfaceShapePtr<3> make_dumbbell_shape<3>(const Vec3&, double, double, double);

}  // namespace pellicle
