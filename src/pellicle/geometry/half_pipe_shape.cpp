// The half pipe of §4.2.2 (diffusion on a deforming half pipe): "one half of a pipe with
// radius 0.25 bent in an arc of radius 0.75". The paper's figure of it (Figure 13, t = 0) is
// lost; this is a reconstruction from the text: the centre line is the arc x = R cos θ,
// z = R sin θ (y = 0) of radius R about the origin, θ ∈ [−arc/2, arc/2] (symmetric about
// z = 0), and the tube of radius ρ around it is cut lengthwise in half. Points of the tube
// are X(θ, φ) = (R + ρ cos φ) e_r(θ) + ρ sin φ e_y with e_r(θ) = (cos θ, 0, sin θ); the half
// kept is φ ∈ [φ0, φ0 + π]: the inner one (facing the arc's centre, φ0 = π/2), the outer
// one (φ0 = −π/2) or the upper one (y ≥ 0, φ0 = 0). The boundary is the two long edges
// (φ = φ0 and φ0 + π) and the two half circles at the ends (θ = ±arc/2).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "pellicle/geometry/shape_support.hpp"
#include "pellicle/geometry/surface_shapes.hpp"

namespace pellicle {
namespace {

constexpr double pi = std::numbers::pi;

class HalfPipeShape final : public SurfaceShape<3> {
 public:
  HalfPipeShape(double pipe_radius, double arc_radius, double arc_angle, HalfPipeSide side)
      : rho_(pipe_radius),
        radius_(arc_radius),
        half_(0.5 * arc_angle),
        phi0_(side == HalfPipeSide::inner   ? 0.5 * pi
              : side == HalfPipeSide::outer ? -0.5 * pi
                                            : 0.0),
        side_(side) {
    const int along =
        std::max(2, static_cast<int>(std::ceil(arc_angle * (radius_ + rho_) / (0.3 * rho_))));
    const int around = static_cast<int>(std::ceil(pi / 0.3));
    carrier_ = parametric_grid(along, around, [this](double u, double v) {
      return at(-half_ + 2.0 * half_ * u, phi0_ + pi * v);
    });
  }

  std::string describe() const override {
    const char* which = side_ == HalfPipeSide::inner   ? "inner"
                        : side_ == HalfPipeSide::outer ? "outer"
                                                       : "upper";
    return std::string(which) + " half pipe of radius " + describe_number(rho_) +
           " along an arc of radius " + describe_number(radius_) + " spanning " +
           describe_number(2.0 * half_ * 180.0 / pi) + " degrees";
  }

  //! In the meridian plane of x (θ clamped to the arc, which is exact: the distance to
  //! X(θ', φ) grows with |θ − θ'|), the nearest point of the half circle.
  Vec3 project(const Vec3& x) const override {
    const auto [theta, phi] = coordinates(x);
    return at(theta, phi);
  }

  //! Away from the centre line: cos φ e_r + sin φ e_y.
  Vec3 normal(const Vec3& x) const override {
    const auto [theta, phi] = coordinates(x);
    return std::cos(phi) * radial(theta) + std::sin(phi) * Vec3::UnitY();
  }

  double surface_error(const Vec3& x) const override { return (x - project(x)).norm(); }

  //! ∫∫ ρ (R + ρ cos φ) dθ dφ over θ ∈ [−arc/2, arc/2], φ ∈ [φ0, φ0 + π].
  double measure() const override {
    return 2.0 * half_ * rho_ * (pi * radius_ - 2.0 * rho_ * std::sin(phi0_));
  }

  PointSample<3> sample(const SamplingOptions& options) const override {
    SampleRandom random(options.seed);
    // The ends first, then the long edges; each curve's ends are the shared corners.
    std::vector<Vec3> boundary;
    const std::vector<BoundaryCurve<3>> curves = {
        {[this](double u) { return at(-half_, phi0_ + pi * u); }, false, 1},
        {[this](double u) { return at(half_, phi0_ + pi * u); }, false, 1},
        {[this](double u) { return at(-half_ + 2.0 * half_ * u, phi0_); }, false, 1},
        {[this](double u) { return at(-half_ + 2.0 * half_ * u, phi0_ + pi); }, false, 1},
    };
    for (const auto& c : curves)
      for (const Vec3& p : boundary_points<3>(c, options.spacing, random)) boundary.push_back(p);
    const Projection<3> onto = [this](const Vec3& x) { return project(x); };
    std::vector<Vec3> candidates;
    for (const Vec3& x :
         carrier_candidates<3>(carrier_, onto, kCandidateCell * options.spacing, random)) {
      const auto [theta, phi] = coordinates(x);
      if (phi > phi0_ && phi < phi0_ + pi && std::abs(theta) < half_) candidates.push_back(x);
    }
    return select_spaced<3>(*this, boundary, std::move(candidates), options.spacing, random);
  }

 private:
  Vec3 radial(double theta) const { return Vec3(std::cos(theta), 0.0, std::sin(theta)); }
  Vec3 at(double theta, double phi) const {
    return (radius_ + rho_ * std::cos(phi)) * radial(theta) + rho_ * std::sin(phi) * Vec3::UnitY();
  }
  //! (θ, φ) of the point of the half pipe nearest to x.
  std::pair<double, double> coordinates(const Vec3& x) const {
    const double theta = std::clamp(std::atan2(x.z(), x.x()), -half_, half_);
    const double s = x.dot(radial(theta)) - radius_;  // in the meridian half-plane
    // φ − (φ0 + π/2) in (−π, π], clamped to the half kept: outside it, the nearer edge.
    const double middle = phi0_ + 0.5 * pi;
    double off = std::atan2(x.y(), s) - middle;
    if (off > pi) off -= 2.0 * pi;
    if (off <= -pi) off += 2.0 * pi;
    return {theta, middle + std::clamp(off, -0.5 * pi, 0.5 * pi)};
  }

  double rho_, radius_, half_, phi0_;
  HalfPipeSide side_;
  std::vector<Simplex<3>> carrier_;
};

}  // namespace

SurfaceShapePtr<3> make_half_pipe_shape(double pipe_radius, double arc_radius, double arc_angle,
                                        HalfPipeSide side) {
  return std::make_unique<HalfPipeShape>(pipe_radius, arc_radius, arc_angle, side);
}

}  // namespace pellicle
