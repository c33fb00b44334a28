// The torus of §3.7.4 and §4.2.3: (c − √(x² + y²))² + z² = a² (eqs 14, 39).
#include <cmath>
#include <numbers>

#include "pellicle/geometry/shape_support.hpp"
#include "pellicle/geometry/surface_shapes.hpp"

namespace pellicle {
namespace {

class TorusShape final : public SurfaceShape<3> {
 public:
  TorusShape(const Vec3& center, double major, double minor)
      : center_(center), major_(major), minor_(minor) {
    carrier_ = carrier_of(make_torus(center, Vec3::UnitZ(), major, minor, 0.3 * minor));
  }

  std::string describe() const override {
    return "torus of major radius " + describe_number(major_) + " and minor radius " +
           describe_number(minor_) + " about the z axis through " + describe_vector<3>(center_);
  }

  //! The nearest point of the tube's circle in the meridian plane through x.
  Vec3 project(const Vec3& x) const override {
    const Vec3 ring = ring_point(x);
    return ring + minor_ * tube_direction(x, ring);
  }

  Vec3 normal(const Vec3& x) const override { return tube_direction(x, ring_point(x)); }

  //! Eq 15: |(c − √(x² + y²))² + z² − a²|.
  double surface_error(const Vec3& x) const override {
    const Vec3 q = x - center_;
    const double rho = std::hypot(q.x(), q.y());
    return std::abs((major_ - rho) * (major_ - rho) + q.z() * q.z() - minor_ * minor_);
  }

  double measure() const override {
    return 4.0 * std::numbers::pi * std::numbers::pi * major_ * minor_;
  }

  PointSample<3> sample(const SamplingOptions& options) const override {
    return sample_closed<3>(*this, carrier_, options);
  }

 private:
  //! The point of the centre circle (radius c) nearest to x.
  Vec3 ring_point(const Vec3& x) const {
    const Vec3 q = x - center_;
    const double rho = std::hypot(q.x(), q.y());
    const Vec3 radial = rho > 0 ? Vec3(q.x() / rho, q.y() / rho, 0.0) : Vec3(Vec3::UnitX());
    return center_ + major_ * radial;
  }
  //! Outward unit normal: from the centre circle towards x.
  Vec3 tube_direction(const Vec3& x, const Vec3& ring) const {
    const Vec3 d = x - ring;
    return d.norm() > 0 ? Vec3(d.normalized()) : Vec3(((ring - center_) / major_).eval());
  }

  Vec3 center_;
  double major_, minor_;
  std::vector<Simplex<3>> carrier_;
};

}  // namespace

SurfaceShapePtr<3> make_torus_shape(const Vec3& center, double major, double minor) {
  return std::make_unique<TorusShape>(center, major, minor);
}

}  // namespace pellicle
