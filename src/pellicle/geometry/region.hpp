#pragma once
//! Regions defined by inequalities, as bodies are defined in the seeds (thesis appendix A.4:
//! polygons and ellipses), with boolean combinations. A region answers "is x inside?" and
//! gives a bounding box (possibly infinite) so fills only visit nearby cells.

#include <memory>
#include <vector>

#include "pellicle/core/types.hpp"

namespace pellicle {

template <int D>
struct Box {
  Vec<D> lower, upper;
};

template <int D>
class Region {
 public:
  virtual ~Region() = default;
  virtual bool contains(const Vec<D>& x) const = 0;
  virtual Box<D> bounds() const = 0;
};

template <int D>
using RegionPtr = std::unique_ptr<Region<D>>;

//! Axis-aligned box lower ≤ x ≤ upper.
template <int D>
RegionPtr<D> make_box(const Vec<D>& lower, const Vec<D>& upper);
//! Disk (2D) or ball (3D): |x − c| ≤ r.
template <int D>
RegionPtr<D> make_ball(const Vec<D>& center, double radius);
//! Axis-aligned ellipse or ellipsoid: Σ ((x − c)_d / a_d)² ≤ 1.
template <int D>
RegionPtr<D> make_ellipsoid(const Vec<D>& center, const Vec<D>& semi_axes);
//! Half-space (x − p) · n ≤ 0: the side the outward normal n points away from.
template <int D>
RegionPtr<D> make_half_space(const Vec<D>& point, const Vec<D>& outward_normal);
//! Solid cylinder (3D): |(x − c)·a| ≤ height/2 and distance from the axis ≤ radius.
RegionPtr<3> make_cylinder_region(const Vec3& center, const Vec3& axis, double radius,
                                  double height);
//! Simple polygon (2D), vertices in either order; even–odd rule.
RegionPtr<2> make_polygon(std::vector<Vec2> vertices);
//! Inside any of the parts.
template <int D>
RegionPtr<D> make_union(std::vector<RegionPtr<D>> parts);
//! Inside all of the parts.
template <int D>
RegionPtr<D> make_intersection(std::vector<RegionPtr<D>> parts);
//! Inside the first part and none of the others.
template <int D>
RegionPtr<D> make_difference(std::vector<RegionPtr<D>> parts);

}  // namespace pellicle
