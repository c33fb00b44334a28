// An open tube: the cylinder of radius ρ about the z axis through `center`, |z − c_z| ≤ L/2.
// Its boundary is the two end circles. Points are X(z, φ) = c + ρ (cos φ, sin φ, 0) + z e_z.
// A stand-in for the infinite cylinder of the curvature flows (Suchde & Kuhnert §4.2.3): the
// flows are measured far from its ends.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "pellicle/geometry/shape_support.hpp"
#include "pellicle/geometry/surface_shapes.hpp"

namespace pellicle {
namespace {

constexpr double pi = std::numbers::pi;

class TubeShape final : public SurfaceShape<3> {
 public:
  TubeShape(const Vec3& center, double radius, double length)
      : center_(center), rho_(radius), half_(0.5 * length) {
    const int along = std::max(2, static_cast<int>(std::ceil(length / (0.3 * rho_))));
    const int around = static_cast<int>(std::ceil(2.0 * pi / 0.3));
    carrier_ = parametric_grid(along, around, [this](double u, double v) {
      return at(-half_ + 2.0 * half_ * u, 2.0 * pi * v);
    });
  }

  std::string describe() const override {
    return "open tube of radius " + describe_number(rho_) + " and length " +
           describe_number(2.0 * half_) + " along z about " + describe_vector<3>(center_);
  }

  Vec3 project(const Vec3& x) const override {
    const Vec3 d = x - center_;
    return at(std::clamp(d.z(), -half_, half_), std::atan2(d.y(), d.x()));
  }

  Vec3 normal(const Vec3& x) const override {
    const Vec3 d = x - center_;
    const double phi = std::atan2(d.y(), d.x());
    return Vec3(std::cos(phi), std::sin(phi), 0.0);
  }

  double surface_error(const Vec3& x) const override { return (x - project(x)).norm(); }

  double measure() const override { return 2.0 * pi * rho_ * 2.0 * half_; }

  PointSample<3> sample(const SamplingOptions& options) const override {
    SampleRandom random(options.seed);
    std::vector<Vec3> boundary;
    for (const double z : {-half_, half_}) {
      const BoundaryCurve<3> circle{[this, z](double u) { return at(z, 2.0 * pi * u); }, true, 1};
      for (const Vec3& p : boundary_points<3>(circle, options.spacing, random))
        boundary.push_back(p);
    }
    const Projection<3> onto = [this](const Vec3& x) { return project(x); };
    std::vector<Vec3> candidates;
    for (const Vec3& x :
         carrier_candidates<3>(carrier_, onto, kCandidateCell * options.spacing, random))
      if (std::abs(x.z() - center_.z()) < half_) candidates.push_back(x);
    return select_spaced<3>(*this, boundary, std::move(candidates), options.spacing, random);
  }

 private:
  Vec3 at(double z, double phi) const {
    return center_ + Vec3(rho_ * std::cos(phi), rho_ * std::sin(phi), z);
  }

  Vec3 center_;
  double rho_, half_;
  std::vector<Simplex<3>> carrier_;
};

}  // namespace

SurfaceShapePtr<3> make_tube_shape(const Vec3& center, double radius, double length) {
  return std::make_unique<TubeShape>(center, radius, length);
}

}  // namespace pellicle
