// Normals of one million membrane points in 3D by the hybrid isosurface method (the issue's
// target: under 2 s on one core). Points on a sphere of radius 1, cell 1/70: about 16 points
// per occupied cell, so most cells take the linear construction and dense ones the quadratic.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "pellicle/normals/isosurface.hpp"

namespace {

using namespace pellicle;

std::vector<Vec3> sphere_points(long n) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Vec3> x(n);
  for (auto& p : x) p = Vec3(g(rng), g(rng), g(rng)).normalized();
  return x;
}

void hybrid_normals(benchmark::State& state) {
  const long n = state.range(0);
  const auto x = sphere_points(n);
  FrameSetup<3> setup;
  setup.cell = 1.0 / state.range(1);
  setup.grid_origin = Vec3::Constant(-1.5);
  IsosurfaceEstimator<3> estimator(setup, IsosurfaceBasis::hybrid);
  std::vector<Vec3> normal(n);
  for (auto _ : state) estimator.gradients(x, 0, n, normal);
  state.SetItemsProcessed(state.iterations() * n);
  double worst = 0.0;
  for (long i = 0; i < n; ++i)
    worst = std::max(worst, std::acos(std::min(1.0, std::abs(normal[i].dot(x[i])))));
  state.counters["max_error_deg"] = worst * 180.0 / 3.141592653589793;
}

BENCHMARK(hybrid_normals)
    ->Args({1000000, 70})
    ->Args({1000000, 35})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
