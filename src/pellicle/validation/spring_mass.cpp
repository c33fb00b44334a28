// Spring–mass (cases/spring_mass.toml; IJNME 1999 §3.1.1, thesis §5.5): the heavy end point
// of a 10-point spring released from rest under gravity oscillates as
//   y(t) = −(mg/k)(1 − cos ωt),  k = AE/L,  ω = sqrt(k/m),
// run at Δt_crit = cell/c (IJNME eq 19). The paper runs it stably at 1.6 Δt_crit and finds
// 1.7 Δt_crit unstable (growing energy); both are checked.
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "pellicle/core/error.hpp"
#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/signals.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

constexpr double kMass = 3.33, kStiffness = 0.1 * 1.0e6 / 0.3, kGravity = 250.0;
constexpr double kCriticalDt = 0.1 / 3162.2776601683795;  // cell / sqrt(E/ρ)

struct Run {
  std::vector<double> t, y;           //!< end-point displacement from its start
  std::vector<double> energy_change;  //!< |E(t) − E(0)|
  double peak_kinetic = 0.0;
  bool failed = false;
  //! Largest energy change in [from, to).
  double change_between(double from, double to) const {
    double m = 0.0;
    for (std::size_t i = 0; i < energy_change.size(); ++i)
      if (t[i + 1] >= from && t[i + 1] < to) m = std::max(m, energy_change[i]);
    return m;
  }
};

Run oscillate(double dt_factor, double end_time) {
  char dt[64];
  std::snprintf(dt, sizeof dt, "solver.dt=%.10g", dt_factor * kCriticalDt);
  auto s = builtin_simulation<2>(
      "spring_mass.toml",
      {dt, "solver.cfl_limit=3", "solver.end_time=" + std::to_string(end_time)});
  const long end_point = s->points().bodies[0].end - 1;
  const double y0 = s->points().position[end_point].y(), e0 = s->state().total();
  Run run;
  run.t = {0.0};
  run.y = {0.0};
  try {
    while (!s->finished()) {
      s->step();
      run.t.push_back(s->time());
      run.y.push_back(s->points().position[end_point].y() - y0);
      const auto state = s->state();
      run.energy_change.push_back(std::abs(state.total() - e0));
      run.peak_kinetic = std::max(run.peak_kinetic, state.kinetic);
    }
  } catch (const NumericalError&) {
    run.failed = true;  // a blown-up run stops with a numerical failure
  }
  return run;
}

}  // namespace

Outcome spring_mass(Resolution) {
  const double omega = std::sqrt(kStiffness / kMass), period = 2.0 * std::numbers::pi / omega;
  const double deflection = kMass * kGravity / kStiffness;
  const Run run = oscillate(1.0, 5.0 * period);
  Outcome out;
  Series series{"spring_mass_displacement",
                "End-mass displacement: MPM at Δt_crit and analytic",
                {"time", "MPM", "analytic"},
                {}};
  double worst = 0.0;
  for (std::size_t i = 0; i < run.t.size(); ++i) {
    const double exact = -deflection * (1.0 - std::cos(omega * run.t[i]));
    worst = std::max(worst, std::abs(run.y[i] - exact));
    if (i % 10 == 0) series.rows.push_back({run.t[i], run.y[i], exact});
  }
  // Oscillation about the static deflection: period from its sign changes, and its range.
  std::vector<double> about(run.y.size());
  for (std::size_t i = 0; i < run.y.size(); ++i) about[i] = run.y[i] + deflection;
  const double measured_period = 2.0 * slope_per_index(sign_changes(run.t, about));
  const double range = -*std::min_element(run.y.begin(), run.y.end());
  constexpr double kPeriodTolerance = 0.01, kRangeTolerance = 0.02;
  out.checks.push_back({"period error over five periods (T = 2π sqrt(m/k) = 0.01988)",
                        100.0 * (measured_period / period - 1.0), 0.0, -100.0 * kPeriodTolerance,
                        100.0 * kPeriodTolerance, "%"});
  out.checks.push_back({"largest displacement / (2mg/k)", range / (2.0 * deflection), 1.0,
                        1.0 - kRangeTolerance, 1.0 + kRangeTolerance, ""});
  // y = −(mg/k)(1 − cos ωt) with ω and the amplitude within the tolerances above deviates by at
  // most (mg/k) (2π · 5 periods · ΔT/T + 2 Δrange/range) over five periods.
  const double drift = 2.0 * std::numbers::pi * 5.0 * kPeriodTolerance + 2.0 * kRangeTolerance;
  out.checks.push_back(
      {"max |y − y_exact| over five periods / (mg/k)", worst / deflection, 0.0, 0.0, drift, ""});
  const Run stable = oscillate(1.6, 5.0 * period), unstable = oscillate(1.7, 5.0 * period);
  // Stable: the energy error oscillates without growing (last period against the first);
  // unstable: it grows by orders of magnitude, or the run stops on a numerical failure.
  const double first = stable.change_between(0.0, period),
               last = stable.change_between(4 * period, 5 * period);
  out.checks.push_back({"1.6 Δt_crit: max |ΔE| in period 5 / in period 1 (stable: no growth)",
                        stable.failed ? 1e9 : last / first, 1.0, 0.0, 2.0, ""});
  out.checks.push_back({"1.6 Δt_crit: max |ΔE| / peak kinetic energy",
                        stable.failed ? 1e9 : last / stable.peak_kinetic, 0.0, 0.0, 0.05, ""});
  const double grown = unstable.failed ? std::numeric_limits<double>::infinity()
                                       : unstable.change_between(4 * period, 5 * period) /
                                             unstable.change_between(0.0, period);
  out.checks.push_back({"1.7 Δt_crit: energy error growth, period 5 / period 1 (unstable)", grown,
                        std::numeric_limits<double>::infinity(), 100.0,
                        std::numeric_limits<double>::infinity(), ""});
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
