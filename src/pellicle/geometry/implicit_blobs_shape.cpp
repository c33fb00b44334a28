// Blobby implicit curves and surfaces: f(x) = Σ_k exp(−|x − c_k|²/r_k²) − level = 0, inside
// where f > 0. A test shape with varying curvature and no parametrisation: the carrier comes
// from marching simplices on a grid, candidates reach f = 0 by Newton steps along ∇f.
#include <algorithm>
#include <cmath>

#include "pellicle/geometry/shape_support.hpp"
#include "pellicle/geometry/surface_shapes.hpp"

namespace pellicle {
namespace {

template <int D>
class ImplicitBlobs final : public SurfaceShape<D> {
 public:
  ImplicitBlobs(std::vector<Vec<D>> centers, std::vector<double> radii, double level)
      : centers_(std::move(centers)), radii_(std::move(radii)), level_(level) {
    // f ≥ 0 needs some term ≥ level/K, so the curve lies within r_k √ln(K/level) of a centre.
    const double k = static_cast<double>(centers_.size());
    const double smallest = *std::min_element(radii_.begin(), radii_.end());
    Vec<D> lower = Vec<D>::Constant(1e308), upper = Vec<D>::Constant(-1e308);
    for (std::size_t i = 0; i < centers_.size(); ++i) {
      const double reach = radii_[i] * std::sqrt(std::log(k / level_));
      lower = lower.cwiseMin(centers_[i] - Vec<D>::Constant(reach));
      upper = upper.cwiseMax(centers_[i] + Vec<D>::Constant(reach));
    }
    // Grid cells a sixth of the smallest blob's own radius (√ln(1/level) r), at most about
    // 2·10⁶ nodes; the margin keeps the zero level set off the box.
    double cell = smallest * std::min(1.0, std::sqrt(std::log(1.0 / level_))) / 6.0;
    const Vec<D> extent = upper - lower + Vec<D>::Constant(4.0 * cell);
    cell = std::max(cell, std::pow(extent.prod() / 2e6, 1.0 / D));
    lower -= Vec<D>::Constant(2.0 * cell);
    upper += Vec<D>::Constant(2.0 * cell);
    carrier_ = zero_level_set<D>([this](const Vec<D>& x) { return value(x); }, lower, upper, cell);
    step_limit_ = 0.25 * smallest;
  }

  std::string describe() const override {
    return "level set Σ exp(−|x − c_k|²/r_k²) = " + describe_number(level_) + " of " +
           std::to_string(centers_.size()) + (centers_.size() == 1 ? " blob" : " blobs");
  }

  //! Newton steps along ∇f, x ← x − f ∇f/|∇f|², each at most a quarter of the smallest
  //! radius long, until the step is below 10⁻¹⁵ of the blob size.
  Vec<D> project(const Vec<D>& x) const override {
    Vec<D> y = x;
    for (int iteration = 0; iteration < 60; ++iteration) {
      const Vec<D> g = gradient(y);
      const double g2 = g.squaredNorm();
      if (g2 == 0.0) break;  // a centre, or far away: no direction to go
      Vec<D> step = (value(y) / g2) * g;
      if (step.norm() > step_limit_) step *= step_limit_ / step.norm();
      y -= step;
      if (step.norm() <= 1e-15 * 4.0 * step_limit_) break;
    }
    return y;
  }

  //! −∇f/|∇f| at the projected point: outward, where f decreases.
  Vec<D> normal(const Vec<D>& x) const override {
    const Vec<D> g = gradient(project(x));
    return g.norm() > 0 ? Vec<D>(-g.normalized()) : Vec<D>(Vec<D>::UnitX());
  }

  double surface_error(const Vec<D>& x) const override { return (x - project(x)).norm(); }

  //! The marching-simplex carrier's: its pieces are a sixth of a blob wide or less.
  double measure() const override { return carrier_measure<D>(carrier_); }

  PointSample<D> sample(const SamplingOptions& options) const override {
    return sample_closed<D>(*this, carrier_, options);
  }

 private:
  double value(const Vec<D>& x) const {
    double f = -level_;
    for (std::size_t k = 0; k < centers_.size(); ++k)
      f += std::exp(-(x - centers_[k]).squaredNorm() / (radii_[k] * radii_[k]));
    return f;
  }
  Vec<D> gradient(const Vec<D>& x) const {
    Vec<D> g = Vec<D>::Zero();
    for (std::size_t k = 0; k < centers_.size(); ++k) {
      const double r2 = radii_[k] * radii_[k];
      const Vec<D> d = x - centers_[k];
      g -= (2.0 / r2) * std::exp(-d.squaredNorm() / r2) * d;
    }
    return g;
  }

  std::vector<Vec<D>> centers_;
  std::vector<double> radii_;
  double level_, step_limit_ = 0.0;
  std::vector<Simplex<D>> carrier_;
};

}  // namespace

template <int D>
SurfaceShapePtr<D> make_implicit_blobs(std::vector<Vec<D>> centers, std::vector<double> radii,
                                       double level) {
  return std::make_unique<ImplicitBlobs<D>>(std::move(centers), std::move(radii), level);
}

template SurfaceShapePtr<2> make_implicit_blobs<2>(std::vector<Vec2>, std::vector<double>, double);
template SurfaceShapePtr<3> make_implicit_blobs<3>(std::vector<Vec3>, std::vector<double>, double);

}  // namespace pellicle
