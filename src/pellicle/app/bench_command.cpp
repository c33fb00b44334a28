//! `pellicle bench`: throughput of the MPM step in particle-steps per second, and the memory a
//! point takes, on problems refined to the requested number of points: solids in 2D and 3D
//! (linear and quadratic kernels, FLIP and APIC), contact, a gas, and gas inside a membrane.
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

#include "pellicle/app/commands.hpp"
#include "pellicle/core/error.hpp"
#include "pellicle/io/bench_case.hpp"

namespace pellicle {

namespace {

//! A benchmark problem of either dimension, seen through what the bench measures.
struct BenchRun {
  std::function<void(long)> run;  //!< advance until this many steps in all
  long points = 0;
  std::size_t state_bytes = 0;  //!< the simulation's own accounting (pellicle check)
};

template <int D>
BenchRun bench_run(std::unique_ptr<Simulation<D>> simulation) {
  std::shared_ptr<Simulation<D>> s = std::move(simulation);
  return {[s](long steps) { s->run(steps); }, s->points().size(), s->memory_estimate_bytes()};
}

struct BenchCase {
  const char* name;
  const char* method;
  std::function<BenchRun(long points)> make;
};

const std::vector<BenchCase>& bench_cases() {
  static const std::vector<BenchCase> cases = {
      {"two-disks", "2D linear MUSL FLIP, linear elastic",
       [](long n) { return bench_run(make_bench_two_disks(n, "linear", "flip")); }},
      {"two-disks-contact", "2D linear MUSL FLIP, release contact (a field per body)",
       [](long n) {
         return bench_run(
             make_bench_two_disks(n, "linear", "flip", {"contact={model=\"release\"}"}));
       }},
      {"gas-box", "2D gas, quadratic B-spline MUSL APIC, energy equation",
       [](long n) { return bench_run(make_bench_gas_box(n, "quadratic-bspline", "apic")); }},
      {"gas-in-membrane", "2D gas in a membrane, quadratic B-spline MUSL APIC",
       [](long n) { return bench_run(make_bench_gas_membrane(n)); }},
      {"two-spheres-3d", "3D quadratic B-spline USL APIC, linear elastic",
       [](long n) {
         return bench_run(make_bench_two_spheres(n, "quadratic-bspline", "apic", "usl"));
       }},
      {"two-spheres-3d-musl", "3D quadratic B-spline MUSL APIC, linear elastic",
       [](long n) {
         return bench_run(make_bench_two_spheres(n, "quadratic-bspline", "apic", "musl"));
       }},
      {"two-spheres-3d-flip", "3D linear MUSL FLIP, linear elastic",
       [](long n) { return bench_run(make_bench_two_spheres(n, "linear", "flip", "musl")); }},
  };
  return cases;
}

//! A line of /proc/self/status in bytes ("VmRSS", "VmHWM"); 0 where there is none.
std::size_t status_bytes(const char* key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::string prefix = std::string(key) + ":";
  while (std::getline(status, line))
    if (line.rfind(prefix, 0) == 0) return std::stoull(line.substr(prefix.size())) * 1024;
  return 0;
}

//! Restart the peak resident size (VmHWM) from the current one; false where Linux refuses.
bool reset_peak_resident() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return static_cast<bool>(clear);
}

struct BenchResult {
  const BenchCase* bench;
  int threads;
  long points, steps;
  double seconds;
  double bytes_per_point;  //!< peak resident growth over building and running, per point
  double state_bytes_per_point;
  double rate() const { return points * steps / seconds; }
};

BenchResult measure(const BenchCase& bench, long points, long steps, int threads) {
  omp_set_num_threads(threads);
  const std::size_t before = status_bytes("VmRSS");
  const bool peak = reset_peak_resident();
  BenchRun run = bench.make(points);
  run.run(3);  // warm caches and scatter buffers
  const auto start = std::chrono::steady_clock::now();
  run.run(3 + steps);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::size_t after = status_bytes(peak ? "VmHWM" : "VmRSS");
  const double resident = after > before ? static_cast<double>(after - before) : 0.0;
  return {&bench,
          threads,
          run.points,
          steps,
          seconds,
          resident / run.points,
          static_cast<double>(run.state_bytes) / run.points};
}

}  // namespace

int command_bench(const BenchOptions& o) {
  const std::vector<int> threads = o.threads.empty() ? std::vector<int>{1, 2} : o.threads;
  std::vector<const BenchCase*> chosen;
  for (const auto& bench : bench_cases())
    if (o.cases.empty() || std::count(o.cases.begin(), o.cases.end(), bench.name))
      chosen.push_back(&bench);
  for (const auto& name : o.cases)
    if (std::none_of(bench_cases().begin(), bench_cases().end(),
                     [&](const BenchCase& b) { return name == b.name; })) {
      std::string known;
      for (const auto& b : bench_cases()) known += std::string(known.empty() ? "" : ", ") + b.name;
      std::fprintf(stderr, "pellicle: error: --case: no benchmark named '%s' (known: %s)\n",
                   name.c_str(), known.c_str());
      return kExitBadInput;
    }
  std::vector<BenchResult> results;
  try {
    for (const BenchCase* bench : chosen) {
      for (int t : threads) {
        results.push_back(measure(*bench, o.points, o.steps, t));
        const auto& r = results.back();
        if (!o.json)
          std::printf(
              "%-20s %-55s threads %d  points %ld  steps %ld  %.3f s  %.3g particle-steps/s  "
              "%.0f bytes/point\n",
              bench->name, bench->method, r.threads, r.points, r.steps, r.seconds, r.rate(),
              r.bytes_per_point);
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
          "  {\"case\": \"%s\", \"method\": \"%s\", \"threads\": %d, \"points\": %ld, "
          "\"steps\": %ld, \"seconds\": %.6g, \"particle_steps_per_second\": %.6g, "
          "\"bytes_per_point\": %.1f, \"state_bytes_per_point\": %.1f, "
          "\"instruction_set\": \"%s\"}%s\n",
          r.bench->name, r.bench->method, r.threads, r.points, r.steps, r.seconds, r.rate(),
          r.bytes_per_point, r.state_bytes_per_point, PELLICLE_INSTRUCTION_SET,
          i + 1 < results.size() ? "," : "");
    }
    std::printf("]\n");
  } else {
    for (const auto& r : results)
      for (const auto& base : results)
        if (base.bench == r.bench && base.threads == threads.front() && r.threads != base.threads)
          std::printf("%s: speed-up with %d threads: %.2fx\n", r.bench->name, r.threads,
                      r.rate() / base.rate());
  }
  return kExitOk;
}

}  // namespace pellicle
