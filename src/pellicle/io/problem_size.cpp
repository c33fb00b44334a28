#include "pellicle/io/problem_size.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
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

template ProblemSize estimate_problem_size<2>(const Case<2>&);
template ProblemSize estimate_problem_size<3>(const Case<3>&);
template void refuse_oversized_problem<2>(const Case<2>&);
template void refuse_oversized_problem<3>(const Case<3>&);

}  // namespace pellicle
