#pragma once
//! The sampling machinery shared by every SurfaceShape (docs/theory/surface-sampling.md).
//!
//! A cloud is made in three steps:
//!  1. boundary points, placed along each boundary curve at equal arc-length steps whose
//!     chords are at least the spacing (Suchde & Kuhnert §3.4: boundary points are spaced
//!     along the boundary on their own);
//!  2. candidates: each shape has a fixed "carrier", segments (D = 2) or triangles (D = 3)
//!     lying close to it; every carrier piece is split into equal sub-pieces no wider than a
//!     quarter of the spacing once mapped onto the shape, one uniformly random point is put
//!     in each sub-piece and projected onto the exact shape (so every point of the shape has
//!     a candidate within about a quarter spacing);
//!  3. greedy Poisson-disk elimination: the boundary points in order, then the candidates
//!     in order of their distance from a randomly chosen candidate (an advancing front, as
//!     the paper's clouds are made, §3.7), each kept when no kept point is closer than the
//!     spacing (a hashed grid of cells twice that size finds the kept points nearby).
//!
//! The result has no two points closer than the spacing and, because the kept set is
//! maximal among the candidates, no point of the shape farther than the spacing plus the
//! candidates' own gap from a kept point. The front packs the points densely (on the unit
//! sphere the median nearest-neighbour distance is 1.016 spacings, the largest hole about
//! 0.9) without a lattice: the candidates are random, so every seed gives another cloud.

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/geometry/surface_shape.hpp"

namespace pellicle {

//! A reproducible stream of random numbers (SplitMix64): the same seed gives the same
//! numbers with every compiler and standard library.
class SampleRandom {
 public:
  explicit SampleRandom(std::uint64_t seed) : state_(seed) {}
  //! The next 64 random bits.
  std::uint64_t bits() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  //! Uniform in [0, 1).
  double uniform() { return static_cast<double>(bits() >> 11) * 0x1.0p-53; }
  //! Uniform in {0, …, n − 1} (the modulo bias is below n / 2⁶⁴).
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(bits() % n); }

 private:
  std::uint64_t state_;
};

//! Points no two of which are closer than a spacing, kept in a hashed grid of cells twice
//! that size: a new point is checked against the 2^D cells nearest to it only.
template <int D>
class SpacedPoints {
 public:
  explicit SpacedPoints(double spacing);
  //! Keep x unless a kept point lies closer than the spacing; true when kept.
  bool try_add(const Vec<D>& x);
  //! The kept points, in the order they were kept.
  const std::vector<Vec<D>>& points() const { return points_; }

 private:
  using Cell = Eigen::Matrix<long long, D, 1>;
  struct Slot {
    std::uint64_t key;
    int head;  //!< last point kept in the cell, −1 for an empty slot
  };
  static std::uint64_t key_of(const Cell& c);
  int head(std::uint64_t key) const;
  void link(std::uint64_t key, int point);
  void grow();

  double spacing_, inverse_;  //!< inverse_: one over the cell size
  std::vector<Vec<D>> points_;
  std::vector<int> next_;  //!< previous point kept in the same cell, −1 at the end
  std::vector<Slot> slots_;
  std::size_t used_ = 0;
};

//! A carrier piece: a segment (D = 2) or a triangle (D = 3) by its corners.
template <int D>
using Simplex = std::array<Vec<D>, D>;

//! Maps a point near the shape onto it.
template <int D>
using Projection = std::function<Vec<D>(const Vec<D>&)>;

//! Step 2: one random point in every sub-piece of every carrier piece, the pieces split into
//! m equal parts per edge (m² triangles, or m segments) so that their mapped edges are at
//! most `cell` long, each point passed through `project` (none: the carrier is the shape).
template <int D>
std::vector<Vec<D>> carrier_candidates(const std::vector<Simplex<D>>& carrier,
                                       const Projection<D>& project, double cell,
                                       SampleRandom& random);

//! A boundary curve x(u), u ∈ [0, 1]; `pieces` > 1 for a curve made of that many smooth
//! pieces of equal parameter length (a polyline), whose joints are sampled exactly.
template <int D>
struct BoundaryCurve {
  std::function<Vec<D>(double)> at;
  bool closed = false;
  int pieces = 1;
};

//! Step 1: points along the curve at equal arc-length steps, as many as the chords between
//! neighbours allow while staying at least `spacing` long. Open curves include both ends;
//! closed curves start at a random arc length.
template <int D>
std::vector<Vec<D>> boundary_points(const BoundaryCurve<D>& curve, double spacing,
                                    SampleRandom& random);

//! Step 3: the boundary points first (flagged), then the candidates by their distance from
//! a random one; each kept when no kept point is closer than `spacing`; normals from the
//! shape.
template <int D>
PointSample<D> select_spaced(const SurfaceShape<D>& shape, const std::vector<Vec<D>>& boundary,
                             std::vector<Vec<D>> candidates, double spacing, SampleRandom& random);

//! Width of the candidates' sub-pieces as a fraction of the spacing (step 2).
inline constexpr double kCandidateCell = 0.25;
//! Distances from the front's origin are ordered to this fraction of the spacing (step 3).
inline constexpr double kFrontResolution = 0.02;

//! Steps 2–3 for a shape without boundary: candidates on `carrier` projected onto the shape
//! by its own closest point, then spaced.
template <int D>
PointSample<D> sample_closed(const SurfaceShape<D>& shape, const std::vector<Simplex<D>>& carrier,
                             const SamplingOptions& options) {
  SampleRandom random(options.seed);
  const Projection<D> onto = [&shape](const Vec<D>& x) { return shape.project(x); };
  return select_spaced<D>(
      shape, {}, carrier_candidates<D>(carrier, onto, kCandidateCell * options.spacing, random),
      options.spacing, random);
}

}  // namespace pellicle
