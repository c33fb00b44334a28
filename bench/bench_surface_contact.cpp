// Cost of contact between point-cloud surfaces (Suchde & Kuhnert §3.6) on the joining
// spheres of §3.7.3 (h = 0.1, two unit spheres, 15,000 points, pressed together at relative
// speed 1): whole steps in points per second,
//   0  both spheres one chamber, no contact (neighbourhoods not split: the plain GFDM step),
//   1  two chambers, no response (S_i split from S_i^ext, nothing detected),
//   2  two chambers with non-penetration (split, eq 10 at every point in contact, projection).
// The ratio of 2 to 1 is the contact's cost per step (mode 0 is no clean baseline: sharing
// neighbourhoods, the touching spheres merge and fill across; docs/theory/surface-contact.md).
#include <benchmark/benchmark.h>

#include <limits>

#include "pellicle/geometry/surface_shapes.hpp"
#include "pellicle/surface/builder.hpp"

namespace {

using namespace pellicle;

std::unique_ptr<SurfaceSimulation<3>> touching_spheres(int mode) {
  const double h = 0.1;
  PointSample<3> sample;
  std::vector<int> surface;
  for (int k = 0; k < 2; ++k) {
    const auto part = make_cut_sphere<3>(Vec3(k ? 1.01 : -1.01, 0.0, 0.0), 1.0, {})
                          ->sample({kPaperSpacingFactor * h, 1u + k});
    sample.points.insert(sample.points.end(), part.points.begin(), part.points.end());
    sample.normals.insert(sample.normals.end(), part.normals.begin(), part.normals.end());
    sample.boundary.insert(sample.boundary.end(), part.boundary.begin(), part.boundary.end());
    surface.insert(surface.end(), part.size(), mode == 0 ? 0 : k);
  }
  SurfaceSettings settings;
  settings.dt = 0.03;
  settings.end_time = std::numeric_limits<double>::infinity();  // the benchmark counts the steps
  settings.smooth_curvature = false;
  if (mode == 2) settings.contact.between = ContactResponse::non_penetration;
  return build_surface_simulation<3>(
      sample, h, settings, {PointFormula("-0.5*sign(x)"), PointFormula("0"), PointFormula("0")},
      nullptr, &surface);
}

void joining_spheres_step(benchmark::State& state) {
  auto s = touching_spheres(static_cast<int>(state.range(0)));
  long points = 0;
  for (auto _ : state) {
    s->step();
    points += s->point_count();
  }
  state.SetItemsProcessed(points);
  state.counters["points"] = static_cast<double>(s->point_count());
  state.counters["in_contact"] = static_cast<double>(s->last_contact().in_contact);
}

BENCHMARK(joining_spheres_step)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Iterations(12)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
