// Per-stage throughput of the MPM step (DESIGN.md's stages 2–7), points per second, single
// thread (set OMP_NUM_THREADS for more): the 2D two-disk problem (linear, FLIP) and the 3D
// two spheres (quadratic B-splines, APIC). docs/theory/performance.md gives the bytes each
// stage moves per point; these figures say which stage to work on.
#include <benchmark/benchmark.h>

#include <vector>

#include "pellicle/io/bench_case.hpp"

namespace {

using namespace pellicle;

template <int D>
std::unique_ptr<Simulation<D>> make_case(long points);
template <>
std::unique_ptr<Simulation<2>> make_case<2>(long points) {
  return make_bench_two_disks(points, "linear", "flip");
}
template <>
std::unique_ptr<Simulation<3>> make_case<3>(long points) {
  return make_bench_two_spheres(points, "quadratic-bspline", "apic", "usl");
}

enum class Stage { stencils, to_grid, grid, to_points, remap, kinematics, material };

//! One stage repeated on the state a few steps into the run; the time step is tiny so that
//! to_points leaves the points where they are.
template <int D>
void stage(benchmark::State& state, Stage which) {
  auto simulation = make_case<D>(state.range(0));
  simulation->run(2);
  auto& points = simulation->points();
  auto& grid = simulation->fields().centre_of_mass();
  auto& transfer = simulation->transfer();
  const double dt = 1e-12;
  const long n = points.size();
  std::vector<Mat<D>> gradient(n, Mat<D>::Zero());
  transfer.compute_stencils(points, grid, {});
  transfer.to_grid(points, simulation->gravity(), grid, true);
  grid.integrate(dt);
  PointFailure failure;
  for (auto _ : state) {
    switch (which) {
      case Stage::stencils:
        transfer.compute_stencils(points, grid, {});
        break;
      case Stage::to_grid:
        transfer.to_grid(points, simulation->gravity(), grid, true);
        break;
      case Stage::grid:
        grid.integrate(dt);
        break;
      case Stage::to_points:
        transfer.to_points(grid, dt, points, failure);
        break;
      case Stage::remap:
        transfer.remap(points, grid);
        grid.velocities_from_momentum();
        break;
      case Stage::kinematics:
        transfer.point_kinematics(grid, dt, points, 0, n, gradient.data(), nullptr);
        break;
      case Stage::material:
        for (const auto& body : points.bodies)
          simulation->material(body.material)
              .update({points, gradient, {}, dt, body.begin, body.end, grid.cell()});
        break;
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * n);
  state.counters["points"] = static_cast<double>(n);
}

void stage_2d(benchmark::State& state, Stage which) {
  stage<2>(state, which);
}
void stage_3d(benchmark::State& state, Stage which) {
  stage<3>(state, which);
}

#define PELLICLE_STAGE(D, name, points) \
  BENCHMARK_CAPTURE(stage_##D##d, name, Stage::name)->Arg(points)->Unit(benchmark::kMillisecond)

PELLICLE_STAGE(2, stencils, 250000);
PELLICLE_STAGE(2, to_grid, 250000);
PELLICLE_STAGE(2, grid, 250000);
PELLICLE_STAGE(2, to_points, 250000);
PELLICLE_STAGE(2, remap, 250000);
PELLICLE_STAGE(2, kinematics, 250000);
PELLICLE_STAGE(2, material, 250000);
PELLICLE_STAGE(3, stencils, 140640);
PELLICLE_STAGE(3, to_grid, 140640);
PELLICLE_STAGE(3, grid, 140640);
PELLICLE_STAGE(3, to_points, 140640);
PELLICLE_STAGE(3, kinematics, 140640);
PELLICLE_STAGE(3, material, 140640);

}  // namespace
