// Free–free elastic bar (cases/elastic_bar_vibration*.toml), L = 1, c = sqrt(E/ρ) = 10,
// started with v = a (x − L/2). Only odd modes cos(nπx/L) are excited, and the mean velocity
// of the right half is
//   v̄(t) = Σ_{n odd} 8 a L/(n³π³) sin(nπ/2) cos(n ω₁ t),  ω₁ = π c/L,
// which changes sign exactly at T/4, 3T/4, … with T = 2L/c = 0.2. The period is measured as
// twice the least-squares spacing of those reversals.
// The clamped–free bar (cases/elastic_bar_fixed_free.toml), started with a uniform velocity,
// has period 4L/c and its mean velocity reverses at T/4, 3T/4, … (d'Alembert): it tests the
// fixed face.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/signals.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

constexpr double kLength = 1.0, kSpeed = 10.0, kGradient = 0.2;
constexpr double kPeriod = 2.0 * kLength / kSpeed;

double exact_right_half_velocity(double t) {
  const double pi = std::numbers::pi;
  double v = 0.0;
  for (int n = 1; n < 400; n += 2)
    v += 8.0 * kGradient * kLength / (n * n * n * pi * pi * pi) * std::sin(n * pi / 2) *
         std::cos(n * pi * kSpeed / kLength * t);
  return v;
}

template <int D>
Check measure(const std::string& kernel, double cell, Series* series) {
  const char* file = D == 2 ? "elastic_bar_vibration.toml" : "elastic_bar_vibration_3d.toml";
  auto s =
      builtin_simulation<D>(file, {"solver.kernel=" + kernel, "grid.cell=" + std::to_string(cell)});
  std::vector<double> t{0.0}, v{body_velocity(*s, 1).x()};
  while (!s->finished()) {
    s->step();
    t.push_back(s->time());
    v.push_back(body_velocity(*s, 1).x());
    if (series) series->rows.push_back({t.back(), v.back(), exact_right_half_velocity(t.back())});
  }
  const double period = 2.0 * slope_per_index(sign_changes(t, v));
  const double error = 100.0 * (period / kPeriod - 1.0);
  char name[160];
  std::snprintf(name, sizeof name, "%dD period error, %s, %d cells along", D, kernel.c_str(),
                static_cast<int>(std::lround(kLength / cell)));
  return {name, error, 0.0, -1.0, 1.0, "%"};
}

Check measure_fixed_free(const std::string& kernel, double cell) {
  auto s = builtin_simulation<2>("elastic_bar_fixed_free.toml",
                                 {"solver.kernel=" + kernel, "grid.cell=" + std::to_string(cell)});
  std::vector<double> t{0.0}, v{body_velocity(*s, 0).x()};
  while (!s->finished()) {
    s->step();
    t.push_back(s->time());
    v.push_back(body_velocity(*s, 0).x());
  }
  const double period = 2.0 * slope_per_index(sign_changes(t, v));
  char name[160];
  std::snprintf(name, sizeof name, "clamped-free period error, %s, %d cells along", kernel.c_str(),
                static_cast<int>(std::lround(kLength / cell)));
  return {name, 100.0 * (period / (2.0 * kPeriod) - 1.0), 0.0, -1.0, 1.0, "%"};
}

}  // namespace

Outcome bar_vibration(Resolution resolution) {
  const bool full = resolution == Resolution::full;
  Outcome out;
  Series series{"bar_velocity",
                "Right-half mean velocity, quadratic B-spline (2D)",
                {"time", "simulated", "exact"},
                {}};
  for (const std::string kernel : {"linear", "ugimp", "quadratic-bspline", "cubic-bspline"}) {
    for (double cell : full ? std::vector<double>{0.05, 0.025, 0.0125} : std::vector<double>{0.05})
      out.checks.push_back(measure<2>(
          kernel, cell, kernel == "quadratic-bspline" && cell == 0.05 ? &series : nullptr));
  }
  for (const std::string kernel : {"linear", "quadratic-bspline"})
    out.checks.push_back(measure<3>(kernel, full ? 0.025 : 0.05, nullptr));
  for (const std::string kernel : {"linear", "ugimp", "quadratic-bspline", "cubic-bspline"})
    out.checks.push_back(measure_fixed_free(kernel, full ? 0.0125 : 0.05));
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
