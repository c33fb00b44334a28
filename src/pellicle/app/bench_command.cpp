//! `pellicle bench`: throughput of the MPM step in particle-steps per second, on the two-disk
//! problem (linear, MUSL, FLIP) and on gas inside a membrane (the quarter circle of Sulsky &
//! York 2000 §8: quadratic B-splines, APIC), each refined to the requested number of points.
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "pellicle/app/commands.hpp"
#include "pellicle/core/error.hpp"
#include "pellicle/io/bench_case.hpp"

namespace pellicle {

namespace {

struct BenchResult {
  const char* name;
  int threads;
  long points, steps;
  double seconds;
};

BenchResult bench(const char* name, Simulation<2>& simulation, long steps, int threads) {
  simulation.run(3);  // warm caches and scatter buffers
  const auto start = std::chrono::steady_clock::now();
  simulation.run(3 + steps);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {name, threads, simulation.points().size(), steps, seconds};
}

}  // namespace

int command_bench(const BenchOptions& o) {
  const std::vector<int> threads = o.threads.empty() ? std::vector<int>{1, 2} : o.threads;
  std::vector<BenchResult> results;
  try {
    for (const char* name : {"two-disks", "gas-in-membrane"}) {
      for (int t : threads) {
        omp_set_num_threads(t);
        const bool disks = std::string(name) == "two-disks";
        auto simulation = disks ? make_bench_two_disks(o.points, "linear", "flip")
                                : make_bench_gas_membrane(o.points);
        results.push_back(bench(name, *simulation, o.steps, t));
        const auto& r = results.back();
        if (!o.json)
          std::printf(
              "%-16s %-26s threads %d  points %ld  steps %ld  %.3f s  %.3g "
              "particle-steps/s\n",
              r.name, disks ? "linear MUSL FLIP" : "quadratic B-spline MUSL APIC", r.threads,
              r.points, r.steps, r.seconds, r.points * r.steps / r.seconds);
      }
    }
  } catch (const InputError& e) {
    return report_input_error(e);
  } catch (const NumericalError& e) {
    std::fprintf(stderr, "pellicle: error: %s\n", e.what());
    return kExitNumericalFailure;
  }
  if (o.json) {
    std::printf("[\n");
    for (std::size_t i = 0; i < results.size(); ++i) {
      const auto& r = results[i];
      std::printf(
          "  {\"case\": \"%s\", \"threads\": %d, \"points\": %ld, \"steps\": %ld, "
          "\"seconds\": %.6g, \"particle_steps_per_second\": %.6g}%s\n",
          r.name, r.threads, r.points, r.steps, r.seconds, r.points * r.steps / r.seconds,
          i + 1 < results.size() ? "," : "");
    }
    std::printf("]\n");
  } else {
    auto rate = [](const BenchResult& r) { return r.points * r.steps / r.seconds; };
    for (const auto& r : results)
      for (const auto& base : results)
        if (std::string(base.name) == r.name && base.threads == threads.front() &&
            r.threads != base.threads)
          std::printf("%s: speed-up with %d threads: %.2fx\n", r.name, r.threads,
                      rate(r) / rate(base));
  }
  return kExitOk;
}

}  // namespace pellicle
