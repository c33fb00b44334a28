#pragma once
//! Smooth curves (D = 2) and surfaces (D = 3) that meshfree surface clouds are generated on
//! and checked against: each shape knows its closest point, its exact normal and how far a
//! point is off it, and fills itself with an irregular cloud of points at a given spacing
//! (Suchde & Kuhnert §2: no two points closer than r_min h, no hole wider than r_max h).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pellicle/core/parameters.hpp"
#include "pellicle/core/types.hpp"

namespace pellicle {

//! A cloud sampled on a shape: positions, the shape's exact unit normals there, and which
//! points lie on the shape's boundary (open shapes: hemisphere rim, pipe ends, arc ends).
template <int D>
struct PointSample {
  std::vector<Vec<D>> points;
  std::vector<Vec<D>> normals;
  std::vector<std::uint8_t> boundary;  //!< 1 on the boundary of the manifold
  std::size_t size() const { return points.size(); }
};

struct SamplingOptions {
  //! Minimum distance between two points; the largest hole is about this size too.
  double spacing = 0.0;
  //! Seed of the irregular placement: the same seed gives the same cloud.
  std::uint64_t seed = 1;
};

//! Spacing / h of the paper's clouds (about 5.9 points per h² of area).
constexpr double kPaperSpacingFactor = 0.4;

template <int D>
class SurfaceShape {
 public:
  virtual ~SurfaceShape() = default;
  //! "sphere of radius 1 about (0, 0, 0)".
  virtual std::string describe() const = 0;
  //! Closest point of the shape to x (for x within a fraction of the shape's smallest
  //! radius of curvature of it).
  virtual Vec<D> project(const Vec<D>& x) const = 0;
  //! Exact unit normal at (or nearest to) x; outward for closed shapes.
  virtual Vec<D> normal(const Vec<D>& x) const = 0;
  //! How far x is off the shape. The paper's measure where it defines one (eq 13,
  //! |‖x − c‖² − r²|/r² for spheres; eq 15 for tori), else the distance |x − project(x)|.
  virtual double surface_error(const Vec<D>& x) const = 0;
  //! Fill the shape with an irregular cloud: no two points closer than options.spacing, no
  //! gap much wider; boundary points placed along the boundary first, flagged.
  virtual PointSample<D> sample(const SamplingOptions& options) const = 0;
};

template <int D>
using SurfaceShapePtr = std::unique_ptr<SurfaceShape<D>>;

//! The shape described by a `[surface.shape]`-style table: `kind = "sphere"` and the keys
//! of that kind (docs/user-guide.md lists them). Problems are recorded on `in`; returns null
//! when the table cannot describe a shape.
template <int D>
SurfaceShapePtr<D> make_surface_shape(ParameterReader& in);

//! Names accepted by make_surface_shape for dimension D.
template <int D>
std::vector<std::string> surface_shape_kinds();

}  // namespace pellicle
