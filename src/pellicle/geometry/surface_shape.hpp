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

//! Spacing per smoothing length h that reproduces the paper's clouds: on the unit sphere
//! Suchde & Kuhnert use N = 480, 1806, 7446, 30054 points for h = 0.4, 0.2, 0.1, 0.05
//! (Tables 2 and 4: about 5.9 points per h² of area, 18 neighbours within h). With
//! spacing = kPaperSpacingFactor · h, sample() gives N = 467, 1882, 7492, 29941 (seed 1;
//! −2.7 %, +4.2 %, +0.6 %, −0.4 %), with 18 neighbours within h on average.
inline constexpr double kPaperSpacingFactor = 0.392;

struct SamplingOptions {
  //! Minimum distance between two points; the largest hole is about this size too.
  double spacing = 0.0;
  //! Seed of the irregular placement: the same seed gives the same cloud.
  std::uint64_t seed = 1;
};

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
  //! Length (D = 2) or area (D = 3) of the shape, within a few per cent: what sizes a cloud
  //! before it is sampled (io/surface_size.hpp).
  virtual double measure() const = 0;
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
//! As above; a mesh's `file` is relative to `base_directory` (the case file's directory).
//! The one-argument form takes it relative to the working directory.
template <int D>
SurfaceShapePtr<D> make_surface_shape(ParameterReader& in, const std::string& base_directory);

//! Names accepted by make_surface_shape for dimension D.
template <int D>
std::vector<std::string> surface_shape_kinds();

}  // namespace pellicle
