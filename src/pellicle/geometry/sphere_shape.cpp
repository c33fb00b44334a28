// Spheres and circles, whole or cut by planes (lines) through the centre: the paper's unit
// sphere (§4.2.1), hemisphere (§3.7.2) and quarter sphere (§3.7.1).
#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <numbers>

#include "pellicle/geometry/shape_support.hpp"
#include "pellicle/geometry/surface_shapes.hpp"

namespace pellicle {
namespace {

constexpr double pi = std::numbers::pi;

//! Two unit vectors spanning the plane normal to n (3D).
std::pair<Vec3, Vec3> plane_basis(const Vec3& n) {
  const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 a = n.cross(helper).normalized();
  return {a, n.cross(a)};
}

template <int D>
class CutSphere final : public SurfaceShape<D> {
 public:
  CutSphere(const Vec<D>& center, double radius, std::vector<Vec<D>> keep)
      : center_(center), radius_(radius) {
    for (auto& n : keep) keep_.push_back(n.normalized());
    fraction_ = kept_fraction();
    if constexpr (D == 3) {
      carrier_ = carrier_of(make_ellipsoid(center, Vec3::Constant(radius), 0.3 * radius));
    } else {
      carrier_ = closed_polygon(
          [&](double u) {
            return Vec2(center + radius * Vec2(std::cos(2 * pi * u), std::sin(2 * pi * u)));
          },
          128);
    }
  }

  std::string describe() const override {
    std::string s = std::string(D == 3 ? "sphere" : "circle") + " of radius " +
                    describe_number(radius_) + " about " + describe_vector<D>(center_);
    for (std::size_t i = 0; i < keep_.size(); ++i)
      s += (i ? ", " : " cut to n·(x − c) ≥ 0 for n = ") + describe_vector<D>(keep_[i]);
    return s;
  }

  Vec<D> project(const Vec<D>& x) const override {
    const Vec<D> radial = center_ + radius_ * direction(x);
    if (kept(radial, 0.0)) return radial;
    // Outside the part: the nearest point of its boundary (the cut curves and their corners).
    Vec<D> best = radial;
    double nearest = std::numeric_limits<double>::infinity();
    auto consider = [&](const Vec<D>& p) {
      if (!kept(p, 1e-12 * radius_) || (p - x).norm() >= nearest) return;
      nearest = (p - x).norm();
      best = p;
    };
    for (std::size_t i = 0; i < keep_.size(); ++i) {
      const Vec<D>& n = keep_[i];
      if constexpr (D == 2) {
        const Vec2 t(-n.y(), n.x());
        consider(center_ + radius_ * t);
        consider(center_ - radius_ * t);
      } else {
        const Vec3 in_plane = (x - center_) - n.dot(x - center_) * n;
        if (in_plane.norm() > 0) consider(center_ + radius_ * in_plane.normalized());
        for (std::size_t j = i + 1; j < keep_.size(); ++j) {
          const Vec3 corner = n.cross(keep_[j]);
          if (corner.norm() < 1e-12) continue;
          consider(center_ + radius_ * corner.normalized());
          consider(center_ - radius_ * corner.normalized());
        }
      }
    }
    return best;
  }

  Vec<D> normal(const Vec<D>& x) const override { return direction(x); }

  double surface_error(const Vec<D>& x) const override {
    // Eq 13 on the part; beyond its rim, how far the nearest point of the part is.
    if (kept(x, 1e-12 * radius_))
      return std::abs((x - center_).squaredNorm() - radius_ * radius_) / (radius_ * radius_);
    return (x - project(x)).norm() / radius_;
  }

  double measure() const override {
    return fraction_ * (D == 3 ? 4.0 * pi * radius_ * radius_ : 2.0 * pi * radius_);
  }

  PointSample<D> sample(const SamplingOptions& options) const override {
    SampleRandom random(options.seed);
    std::vector<Vec<D>> boundary;
    if constexpr (D == 2) {
      for (const auto& n : keep_)
        for (double side : {1.0, -1.0}) {
          const Vec2 p = center_ + side * radius_ * Vec2(-n.y(), n.x());
          if (kept(p, 1e-12 * radius_)) boundary.push_back(p);
        }
    } else {
      for (std::size_t i = 0; i < keep_.size(); ++i)
        for (const Vec3& p : rim_points(i, options.spacing, random)) boundary.push_back(p);
    }
    const Projection<D> radial = [this](const Vec<D>& x) {
      return Vec<D>(center_ + radius_ * direction(x));
    };
    std::vector<Vec<D>> candidates;
    for (const Vec<D>& x :
         carrier_candidates<D>(carrier_, radial, kCandidateCell * options.spacing, random))
      if (strictly_inside(x)) candidates.push_back(x);
    return select_spaced<D>(*this, boundary, std::move(candidates), options.spacing, random);
  }

 private:
  Vec<D> direction(const Vec<D>& x) const {
    const Vec<D> r = x - center_;
    return r.norm() > 0 ? Vec<D>(r.normalized()) : Vec<D>(Vec<D>::UnitX());
  }
  //! n·(x − c) ≥ −tolerance for every cut.
  bool kept(const Vec<D>& x, double tolerance) const {
    for (const auto& n : keep_)
      if (n.dot(x - center_) < -tolerance) return false;
    return true;
  }
  //! The share of the whole shape the cuts keep: of evenly spread directions (Fibonacci
  //! points on the sphere, equal angles on the circle), those on the kept side of every cut.
  double kept_fraction() const {
    if (keep_.empty()) return 1.0;
    const int count = D == 3 ? 20000 : 3600;
    int kept = 0;
    for (int k = 0; k < count; ++k) {
      Vec<D> d;
      if constexpr (D == 2) {
        const double t = 2 * pi * (k + 0.5) / count;
        d = Vec2(std::cos(t), std::sin(t));
      } else {
        const double z = 1.0 - 2.0 * (k + 0.5) / count, r = std::sqrt(1.0 - z * z);
        const double t = k * pi * (3.0 - std::sqrt(5.0));
        d = Vec3(r * std::cos(t), r * std::sin(t), z);
      }
      kept += strictly_inside(center_ + d);
    }
    return static_cast<double>(kept) / count;
  }
  bool strictly_inside(const Vec<D>& x) const {
    for (const auto& n : keep_)
      if (n.dot(x - center_) <= 0.0) return false;
    return true;
  }

  //! The part of cut circle i that the other cuts keep, sampled at the spacing (3D).
  std::vector<Vec3> rim_points(std::size_t i, double spacing, SampleRandom& random) const
      requires(D == 3) {
    const auto [a, b] = plane_basis(keep_[i]);
    // Each other cut keeps a half circle, α cos t + β sin t ≥ 0; their intersection is one
    // arc [from, to] (intersections of half circles stay connected).
    double from = 0.0, to = 2 * pi;
    bool whole = true;
    for (std::size_t j = 0; j < keep_.size(); ++j) {
      if (j == i) continue;
      const double alpha = keep_[j].dot(a), beta = keep_[j].dot(b);
      if (std::hypot(alpha, beta) < 1e-12) continue;  // the same plane: no further cut
      double middle = std::atan2(beta, alpha);
      if (!whole) middle += 2 * pi * std::round((0.5 * (from + to) - middle) / (2 * pi));
      const double lo = middle - 0.5 * pi, hi = middle + 0.5 * pi;
      if (whole) {
        from = lo, to = hi, whole = false;
      } else {
        from = std::max(from, lo), to = std::min(to, hi);
      }
      if (to <= from) return {};
    }
    const Vec3 c = center_;
    const double r = radius_, start = from, sweep = to - from;
    BoundaryCurve<3> arc{[=](double u) {
                           const double t = start + u * sweep;
                           return Vec3(c + r * (std::cos(t) * a + std::sin(t) * b));
                         },
                         whole, 1};
    return boundary_points<3>(arc, spacing, random);
  }

  Vec<D> center_;
  double radius_;
  std::vector<Vec<D>> keep_;
  double fraction_ = 1.0;  //!< of the whole sphere (circle) the cuts keep
  std::vector<Simplex<D>> carrier_;
};

}  // namespace

template <int D>
SurfaceShapePtr<D> make_cut_sphere(const Vec<D>& center, double radius, std::vector<Vec<D>> keep) {
  return std::make_unique<CutSphere<D>>(center, radius, std::move(keep));
}

template SurfaceShapePtr<2> make_cut_sphere<2>(const Vec2&, double, std::vector<Vec2>);
template SurfaceShapePtr<3> make_cut_sphere<3>(const Vec3&, double, std::vector<Vec3>);

}  // namespace pellicle
