// Particle-steps per second of the full MPM step on the two-disk problem (also with
// contact-release) and on a box of compressing gas, per kernel and velocity update, single thread
// (set OMP_NUM_THREADS for more).
#include <benchmark/benchmark.h>

#include "pellicle/io/bench_case.hpp"

namespace {

using namespace pellicle;

//! Time steps of a simulation after two warm-up steps; items are particle-steps.
void measure(benchmark::State& state, Simulation<2>& simulation) {
  simulation.run(2);
  for (auto _ : state) simulation.step();
  state.SetItemsProcessed(state.iterations() * simulation.points().size());
  state.counters["points"] = static_cast<double>(simulation.points().size());
}

void step(benchmark::State& state, const std::string& kernel, const std::string& update) {
  measure(state, *make_bench_two_disks(state.range(0), kernel, update));
}

BENCHMARK_CAPTURE(step, linear_flip, "linear", "flip")->Arg(250000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(step, quadratic_apic, "quadratic-bspline", "apic")
    ->Arg(250000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(step, quadratic_flip, "quadratic-bspline", "flip")
    ->Arg(250000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(step, cubic_flip, "cubic-bspline", "flip")
    ->Arg(250000)
    ->Unit(benchmark::kMillisecond);

void release_step(benchmark::State& state) {
  measure(state,
          *make_bench_two_disks(state.range(0), "linear", "flip", {"contact={model=\"release\"}"}));
}

BENCHMARK(release_step)->Arg(250000)->Unit(benchmark::kMillisecond);

void gas_step(benchmark::State& state, const std::string& kernel, const std::string& update) {
  measure(state, *make_bench_gas_box(state.range(0), kernel, update));
}

BENCHMARK_CAPTURE(gas_step, quadratic_apic, "quadratic-bspline", "apic")
    ->Arg(250000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(gas_step, linear_flip, "linear", "flip")
    ->Arg(250000)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
