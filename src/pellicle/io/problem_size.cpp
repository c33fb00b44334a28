#include "pellicle/io/problem_size.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

namespace pellicle {

namespace {

// Bytes a point and a grid node (per field) hold in a run, rounded up from the columns and
// stencils of the largest models (3D, quadratic B-spline stencils, APIC): measured resident
// sizes are about 1 kB per point in 2D runs.
constexpr double kBytesPerPoint = 1536.0;
constexpr double kBytesPerNodeField = 160.0;
constexpr double kBytesPerNodeThread = 64.0;  // each extra thread's scatter copy
constexpr int kGhostLayers = 3;

template <int D>
double overlap_volume(const Box<D>& box, const Case<D>& c) {
  double volume = 1.0;
  for (int d = 0; d < D; ++d) {
    const double lo = std::max(box.lower[d], c.lower[d]), hi = std::min(box.upper[d], c.upper[d]);
    volume *= std::max(0.0, hi - lo);
  }
  return volume;
}

template <int D>
Box<D> bounds_of(const std::vector<Vec<D>>& points) {
  Box<D> b{points.front(), points.front()};
  for (const auto& x : points) b.lower = b.lower.cwiseMin(x), b.upper = b.upper.cwiseMax(x);
  return b;
}

std::string gigabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
  return text;
}

}  // namespace

template <int D>
ProblemSize estimate_problem_size(const Case<D>& c) {
  ProblemSize size;
  double nodes = 1.0;
  for (int d = 0; d < D; ++d)
    nodes *= std::round((c.upper[d] - c.lower[d]) / c.cell) + 1 + 2 * kGhostLayers;
  const double fields = c.contact ? 1.0 + static_cast<double>(c.bodies.size()) : 1.0;
  size.nodes = nodes * fields;
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    const auto& body = c.bodies[b];
    double points = 0.0;
    if (body.membrane) {
      points = static_cast<double>(body.membrane->points.size());
    } else {
      // Fills sample the region's bounding box (within the grid) at points_per_cell per
      // direction; a body inside a membrane fills that membrane's bounding box.
      const double per_volume = std::pow(body.points_per_cell / c.cell, D);
      if (body.region) {
        points = overlap_volume(body.region->bounds(), c) * per_volume;
      } else if (!body.inside.empty()) {
        for (const auto& other : c.bodies)
          if (other.name == body.inside && other.membrane && !other.membrane->points.empty())
            points = overlap_volume(bounds_of(other.membrane->points), c) * per_volume;
      }
    }
    size.points += points;
    if (points > size.largest_body_points)
      size.largest_body_points = points, size.largest_body = static_cast<int>(b);
  }
  const double threads = std::max(1, omp_get_max_threads());
  size.bytes = size.points * kBytesPerPoint + size.nodes * kBytesPerNodeField +
               nodes * (threads - 1.0) * kBytesPerNodeThread;
  return size;
}

double available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  double value = 0.0;
  while (meminfo >> key >> value >> unit)
    if (key == "MemAvailable:") return value * 1024.0;
  return 0.0;
}

double most_points_in_memory() {
  const double available = available_memory_bytes();
  return available > 0.0 ? available / kBytesPerPoint : std::numeric_limits<double>::infinity();
}

template <int D>
void refuse_oversized_problem(const Case<D>& c) {
  const ProblemSize size = estimate_problem_size(c);
  const double available = available_memory_bytes();
  if (available <= 0.0 || size.bytes <= available) return;
  char text[400];
  std::snprintf(text, sizeof text,
                "the problem needs about %s (%.3g points, %.3g grid nodes), more than the %s "
                "this machine has available",
                gigabytes(size.bytes).c_str(), size.points, size.nodes,
                gigabytes(available).c_str());
  const double point_bytes = size.points * kBytesPerPoint;
  if (size.largest_body >= 0 && point_bytes >= 0.5 * size.bytes) {
    const auto& body = c.bodies[size.largest_body];
    char why[200];
    std::snprintf(
        why, sizeof why, "; body '%s' alone has about %.3g points: %s", body.name.c_str(),
        size.largest_body_points,
        body.membrane ? "raise its membrane spacing" : "lower points_per_cell or raise grid.cell");
    throw InputError(body.where, "body[" + std::to_string(size.largest_body) + "]",
                     std::string(text) + why);
  }
  throw InputError(c.cell_where, "grid.cell", std::string(text) + "; raise grid.cell");
}

// A surface cloud at spacing s holds about 0.915 points per s² of area (3D: the unit sphere
// at h = 0.1 and 0.8, 7492 and 478215 points) and 0.88 per s of length (2D: circles of
// radius 100 to 1600, h = 0.1). Measured peak resident sizes of `pellicle run` (two steps,
// one or two threads, /usr/bin/time -v) grow by 3.3-3.5 kB a point in 3D (spheres of 120k
// and 480k points, the advection-diffusion and the wave PDE) and 1.42 kB in 2D (circles of
// 56k and 226k points): the sampling's candidates, the cloud's columns, neighbour lists,
// stencils and the implicit solver with its ILU factors. The factors below add about 15 %.
constexpr double kSurfacePointsPerSpacing[2] = {0.88, 0.915};  // per s (2D), per s² (3D)
constexpr double kSurfaceBytesPerPoint[2] = {1700.0, 4096.0};
//! Clouds are indexed with int (neighbour lists, the sampling's hashed grid).
constexpr double kMostSurfacePoints = 2147483647.0;
constexpr const char* kSurfaceRemedy =
    "raise surface.smoothing_length (or spacing_factor) or shrink the shape";

template <int D>
double surface_bytes_per_point() {
  return kSurfaceBytesPerPoint[D - 2];
}

template <int D>
SurfaceSize estimate_surface_size(const SurfaceShape<D>& shape, double spacing) {
  return estimate_surface_size<D>(std::vector<const SurfaceShape<D>*>{&shape}, spacing);
}

template <int D>
SurfaceSize estimate_surface_size(const std::vector<const SurfaceShape<D>*>& shapes,
                                  double spacing) {
  SurfaceSize size;
  for (const SurfaceShape<D>* shape : shapes) size.measure += shape->measure();
  // Divided step by step: (length / s) / s never overflows where length / s² might not.
  double points = size.measure / spacing;
  if constexpr (D == 3) points /= spacing;
  points *= kSurfacePointsPerSpacing[D - 2];
  size.points =
      std::isfinite(points) ? std::max(points, 1.0) : std::numeric_limits<double>::infinity();
  size.bytes = size.points * surface_bytes_per_point<D>();
  return size;
}

template <int D>
void refuse_oversized_surface(const std::vector<const SurfaceShape<D>*>& shapes, double spacing,
                              const SourceLocation& where, const std::string& key) {
  const SurfaceSize size = estimate_surface_size<D>(shapes, spacing);
  const double available = available_memory_bytes();
  char text[400];
  if (!(size.points <= kMostSurfacePoints)) {
    std::snprintf(text, sizeof text,
                  "the initial cloud would hold about %.3g points (%s %.3g at spacing %.3g), "
                  "more than the %.3g a cloud can index: %s",
                  size.points, D == 2 ? "length" : "area", size.measure, spacing,
                  kMostSurfacePoints, kSurfaceRemedy);
    throw InputError(where, key, text);
  }
  if (available <= 0.0 || size.bytes <= available) return;
  std::snprintf(text, sizeof text,
                "the problem needs about %s (%.3g points: %s %.3g at spacing %.3g), more than "
                "the %s this machine has available: %s",
                gigabytes(size.bytes).c_str(), size.points, D == 2 ? "length" : "area",
                size.measure, spacing, gigabytes(available).c_str(), kSurfaceRemedy);
  throw InputError(where, key, text);
}

template SurfaceSize estimate_surface_size<2>(const SurfaceShape<2>&, double);
template SurfaceSize estimate_surface_size<3>(const SurfaceShape<3>&, double);
template SurfaceSize estimate_surface_size<2>(const std::vector<const SurfaceShape<2>*>&, double);
template SurfaceSize estimate_surface_size<3>(const std::vector<const SurfaceShape<3>*>&, double);
template double surface_bytes_per_point<2>();
template double surface_bytes_per_point<3>();
template void refuse_oversized_surface<2>(const std::vector<const SurfaceShape<2>*>&, double,
                                          const SourceLocation&, const std::string&);
template void refuse_oversized_surface<3>(const std::vector<const SurfaceShape<3>*>&, double,
                                          const SourceLocation&, const std::string&);
template ProblemSize estimate_problem_size<2>(const Case<2>&);
template ProblemSize estimate_problem_size<3>(const Case<3>&);
template void refuse_oversized_problem<2>(const Case<2>&);
template void refuse_oversized_problem<3>(const Case<3>&);

}  // namespace pellicle
