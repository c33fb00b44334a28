//! `pellicle bench`: throughput of the MPM step on the two-disk problem (the default case,
//! refined to the requested number of points), in particle-steps per second.
#include <omp.h>

#include <chrono>
#include <cstdio>

#include "pellicle/app/commands.hpp"
#include "pellicle/core/error.hpp"
#include "pellicle/io/bench_case.hpp"

namespace pellicle {

namespace {

struct BenchResult {
  int threads;
  long points, steps;
  double seconds;
};

BenchResult bench_two_disks(long target_points, long steps, int threads) {
  omp_set_num_threads(threads);
  auto simulation = make_bench_two_disks(target_points, "linear", "flip");
  simulation->run(3);  // warm caches and scatter buffers
  const auto start = std::chrono::steady_clock::now();
  simulation->run(3 + steps);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {threads, simulation->points().size(), steps, seconds};
}

}  // namespace

int command_bench(const BenchOptions& o) {
  const std::vector<int> threads = o.threads.empty() ? std::vector<int>{1, 2} : o.threads;
  std::vector<BenchResult> results;
  try {
    for (int t : threads) {
      results.push_back(bench_two_disks(o.points, o.steps, t));
      const auto& r = results.back();
      if (!o.json)
        std::printf(
            "two-disks  linear MUSL FLIP  threads %d  points %ld  steps %ld  %.3f s  "
            "%.3g particle-steps/s\n",
            r.threads, r.points, r.steps, r.seconds, r.points * r.steps / r.seconds);
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
          "  {\"case\": \"two-disks\", \"threads\": %d, \"points\": %ld, \"steps\": %ld, "
          "\"seconds\": %.6g, \"particle_steps_per_second\": %.6g}%s\n",
          r.threads, r.points, r.steps, r.seconds, r.points * r.steps / r.seconds,
          i + 1 < results.size() ? "," : "");
    }
    std::printf("]\n");
  } else if (results.size() >= 2) {
    const double base = results[0].points * results[0].steps / results[0].seconds;
    for (std::size_t i = 1; i < results.size(); ++i)
      std::printf("speed-up with %d threads: %.2fx\n", results[i].threads,
                  results[i].points * results[i].steps / results[i].seconds / base);
  }
  return kExitOk;
}

}  // namespace pellicle
