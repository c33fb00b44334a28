// Throughput of the meshfree surface machinery (Suchde & Kuhnert §3–4) on the paper's unit
// sphere clouds (about 18 neighbours per point), in points per second: neighbour search,
// frames (eq 4), GFDM stencil construction (eqs 17–27), one implicit diffusion step
// (assembly and BiCGSTAB, eq 29, with either preconditioner).
#include <benchmark/benchmark.h>

#include "pellicle/geometry/surface_shapes.hpp"
#include "pellicle/surface/frames.hpp"
#include "pellicle/surface/gfdm.hpp"
#include "pellicle/surface/simulation.hpp"
#include "pellicle/surface/sparse_system.hpp"

namespace {

using namespace pellicle;

struct SphereCloud {
  PointCloud<3> cloud;
  PointSample<3> sample;
  NeighbourSearch<3> search;
  NeighbourLists neighbours;
  SurfaceStencils<3> stencils;
  explicit SphereCloud(double h) {
    sample = make_cut_sphere<3>(Vec3::Zero(), 1.0, {})->sample({kPaperSpacingFactor * h, 1});
    for (const auto& x : sample.points) cloud.add_point(x, h, false);
    search.find(cloud, neighbours);
    estimate_frames(cloud, neighbours, FrameOptions{}, false);
    orient_consistently(cloud, neighbours, &sample.normals);
    build_stencils(cloud, neighbours, GfdmOptions{}, stencils);
  }
};

void points_per_second(benchmark::State& state, std::size_t n) {
  state.SetItemsProcessed(state.iterations() * static_cast<long>(n));
  state.counters["points"] = static_cast<double>(n);
}

void neighbour_search(benchmark::State& state) {
  SphereCloud s(1.0 / state.range(0));
  for (auto _ : state) {
    NeighbourSearch<3> fresh;  // a rebuilt tree each time
    fresh.find(s.cloud, s.neighbours);
  }
  points_per_second(state, s.cloud.size());
}

void frames(benchmark::State& state) {
  SphereCloud s(1.0 / state.range(0));
  for (auto _ : state) estimate_frames(s.cloud, s.neighbours, FrameOptions{}, true);
  points_per_second(state, s.cloud.size());
}

void stencils(benchmark::State& state) {
  SphereCloud s(1.0 / state.range(0));
  for (auto _ : state) build_stencils(s.cloud, s.neighbours, GfdmOptions{}, s.stencils);
  points_per_second(state, s.cloud.size());
}

//! (1/Δt − Δ_M) φⁿ⁺¹ = φⁿ/Δt with Δt = 0.4 h²: assembly and solve.
void implicit_step(benchmark::State& state) {
  const double h = 1.0 / state.range(0), dt = 0.4 * h * h;
  SphereCloud s(h);
  const auto& nb = s.neighbours;
  SparseSystem system;
  LinearSolverOptions options;
  options.preconditioner = state.range(1) ? Preconditioner::jacobi : Preconditioner::ilu;
  std::vector<double> phi(s.cloud.size()), rhs(s.cloud.size());
  for (std::size_t i = 0; i < phi.size(); ++i)
    phi[i] = s.cloud.position[i].x() * s.cloud.position[i].y();
  for (auto _ : state) {
    system.values.resize(nb.index.size());
    for (std::size_t i = 0; i < phi.size(); ++i) {
      for (long k = nb.begin(i); k < nb.end(i); ++k)
        system.values[k] = (k == nb.begin(i) ? 1.0 / dt : 0.0) - s.stencils.laplacian[k];
      rhs[i] = phi[i] / dt;
    }
    system.solve(nb, rhs, phi, options);
  }
  points_per_second(state, phi.size());
}

BENCHMARK(neighbour_search)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(frames)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(stencils)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(implicit_step)
    ->Args({10, 0})
    ->Args({20, 0})
    ->Args({10, 1})
    ->Args({20, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
