#include "pellicle/geometry/region.hpp"

#include <cmath>
#include <limits>

namespace pellicle {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <int D>
Box<D> unbounded() {
  return {Vec<D>::Constant(-kInf), Vec<D>::Constant(kInf)};
}

template <int D>
class BoxRegion final : public Region<D> {
 public:
  BoxRegion(const Vec<D>& lo, const Vec<D>& hi) : box_{lo, hi} {}
  bool contains(const Vec<D>& x) const override {
    return (x.array() >= box_.lower.array()).all() && (x.array() <= box_.upper.array()).all();
  }
  Box<D> bounds() const override { return box_; }

 private:
  Box<D> box_;
};

template <int D>
class Ellipsoid final : public Region<D> {
 public:
  Ellipsoid(const Vec<D>& c, const Vec<D>& a) : center_(c), semi_(a) {}
  bool contains(const Vec<D>& x) const override {
    return ((x - center_).array() / semi_.array()).square().sum() <= 1.0;
  }
  Box<D> bounds() const override { return {center_ - semi_, center_ + semi_}; }

 private:
  Vec<D> center_, semi_;
};

template <int D>
class HalfSpace final : public Region<D> {
 public:
  HalfSpace(const Vec<D>& p, const Vec<D>& n) : point_(p), normal_(n) {}
  bool contains(const Vec<D>& x) const override { return (x - point_).dot(normal_) <= 0.0; }
  Box<D> bounds() const override { return unbounded<D>(); }

 private:
  Vec<D> point_, normal_;
};

class Cylinder final : public Region<3> {
 public:
  Cylinder(const Vec3& c, const Vec3& axis, double r, double h)
      : center_(c), axis_(axis.normalized()), radius_(r), half_(0.5 * h) {}
  bool contains(const Vec3& x) const override {
    const Vec3 d = x - center_;
    const double along = d.dot(axis_);
    return std::abs(along) <= half_ && (d - along * axis_).squaredNorm() <= radius_ * radius_;
  }
  Box<3> bounds() const override {
    const double reach = radius_ + half_;  // generous: covers every orientation
    return {center_ - Vec3::Constant(reach), center_ + Vec3::Constant(reach)};
  }

 private:
  Vec3 center_, axis_;
  double radius_, half_;
};

class Polygon final : public Region<2> {
 public:
  explicit Polygon(std::vector<Vec2> v) : vertices_(std::move(v)) {
    box_.lower = box_.upper = vertices_.front();
    for (const auto& p : vertices_) {
      box_.lower = box_.lower.cwiseMin(p);
      box_.upper = box_.upper.cwiseMax(p);
    }
  }
  bool contains(const Vec2& x) const override {
    // Even–odd crossing rule; points on an edge count as inside.
    bool inside = false;
    const std::size_t n = vertices_.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      const Vec2& a = vertices_[i];
      const Vec2& b = vertices_[j];
      const Vec2 ab = b - a, ax = x - a;
      const double cross = ab.x() * ax.y() - ab.y() * ax.x();
      if (std::abs(cross) <= 1e-12 * ab.norm() && ax.dot(x - b) <= 0.0) return true;
      if ((a.y() > x.y()) != (b.y() > x.y()) &&
          x.x() < (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y()) + a.x())
        inside = !inside;
    }
    return inside;
  }
  Box<2> bounds() const override { return box_; }

 private:
  std::vector<Vec2> vertices_;
  Box<2> box_;
};

enum class Combine { any, all, first_but_not_others };

template <int D>
class Boolean final : public Region<D> {
 public:
  Boolean(Combine how, std::vector<RegionPtr<D>> parts) : how_(how), parts_(std::move(parts)) {}
  bool contains(const Vec<D>& x) const override {
    switch (how_) {
      case Combine::any:
        for (const auto& p : parts_)
          if (p->contains(x)) return true;
        return false;
      case Combine::all:
        for (const auto& p : parts_)
          if (!p->contains(x)) return false;
        return true;
      case Combine::first_but_not_others:
        if (!parts_.front()->contains(x)) return false;
        for (std::size_t i = 1; i < parts_.size(); ++i)
          if (parts_[i]->contains(x)) return false;
        return true;
    }
    return false;
  }
  Box<D> bounds() const override {
    if (how_ == Combine::first_but_not_others) return parts_.front()->bounds();
    Box<D> box = parts_.front()->bounds();
    for (std::size_t i = 1; i < parts_.size(); ++i) {
      const Box<D> b = parts_[i]->bounds();
      if (how_ == Combine::any) {
        box.lower = box.lower.cwiseMin(b.lower);
        box.upper = box.upper.cwiseMax(b.upper);
      } else {
        box.lower = box.lower.cwiseMax(b.lower);
        box.upper = box.upper.cwiseMin(b.upper);
      }
    }
    return box;
  }

 private:
  Combine how_;
  std::vector<RegionPtr<D>> parts_;
};

}  // namespace

template <int D>
RegionPtr<D> make_box(const Vec<D>& lower, const Vec<D>& upper) {
  return std::make_unique<BoxRegion<D>>(lower, upper);
}
template <int D>
RegionPtr<D> make_ball(const Vec<D>& center, double radius) {
  return std::make_unique<Ellipsoid<D>>(center, Vec<D>::Constant(radius));
}
template <int D>
RegionPtr<D> make_ellipsoid(const Vec<D>& center, const Vec<D>& semi_axes) {
  return std::make_unique<Ellipsoid<D>>(center, semi_axes);
}
template <int D>
RegionPtr<D> make_half_space(const Vec<D>& point, const Vec<D>& outward_normal) {
  return std::make_unique<HalfSpace<D>>(point, outward_normal);
}
RegionPtr<3> make_cylinder_region(const Vec3& center, const Vec3& axis, double radius,
                                  double height) {
  return std::make_unique<Cylinder>(center, axis, radius, height);
}
RegionPtr<2> make_polygon(std::vector<Vec2> vertices) {
  return std::make_unique<Polygon>(std::move(vertices));
}
template <int D>
RegionPtr<D> make_union(std::vector<RegionPtr<D>> parts) {
  return std::make_unique<Boolean<D>>(Combine::any, std::move(parts));
}
template <int D>
RegionPtr<D> make_intersection(std::vector<RegionPtr<D>> parts) {
  return std::make_unique<Boolean<D>>(Combine::all, std::move(parts));
}
template <int D>
RegionPtr<D> make_difference(std::vector<RegionPtr<D>> parts) {
  return std::make_unique<Boolean<D>>(Combine::first_but_not_others, std::move(parts));
}

#define PELLICLE_REGION_INSTANTIATE(D)                                    \
  template RegionPtr<D> make_box<D>(const Vec<D>&, const Vec<D>&);        \
  template RegionPtr<D> make_ball<D>(const Vec<D>&, double);              \
  template RegionPtr<D> make_ellipsoid<D>(const Vec<D>&, const Vec<D>&);  \
  template RegionPtr<D> make_half_space<D>(const Vec<D>&, const Vec<D>&); \
  template RegionPtr<D> make_union<D>(std::vector<RegionPtr<D>>);         \
  template RegionPtr<D> make_intersection<D>(std::vector<RegionPtr<D>>);  \
  template RegionPtr<D> make_difference<D>(std::vector<RegionPtr<D>>);
PELLICLE_REGION_INSTANTIATE(2)
PELLICLE_REGION_INSTANTIATE(3)
#undef PELLICLE_REGION_INSTANTIATE

}  // namespace pellicle
