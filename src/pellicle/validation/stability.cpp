// Stability of the explicit step (thesis §8.4–8.5, cases/stability_bar.toml): five points of
// an elastic bar, the middle one kicked. The von Neumann analysis gives the critical time
// step 2 h/c with the points at the cell centres and h/c with the points beside the nodes;
// the thesis's runs first went unstable at 2.0 and 1.1 times h/c. Here the factor is found
// by bisection: a step is unstable when the total energy grows tenfold within 200 steps
// (an amplification of 1.006 per step, so the bisection lands just above the critical
// factor). Checked: the centre case's factor within 10 % of 2.0, the side case's within
// [0.95, 1.2] of the analysis's 1.0 (the thesis's runs: 1.1). Derivation of both limits:
// docs/theory/stability.md.
#include <cmath>
#include <cstdio>
#include <string>

#include "pellicle/core/error.hpp"
#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

constexpr double kCflStep = 1.0e-3;  // h / c: cell 1, c = sqrt(1e6 / 1)
constexpr int kSteps = 200;

//! Whether the bar with its points starting at x0 + k is unstable at dt = factor h/c.
bool unstable(double x0, double factor) {
  char vertices[96], dt[48], end[48];
  std::snprintf(vertices, sizeof vertices, "body[0].membrane.vertices=[[%.10g, 0.5], [%.10g, 0.5]]",
                x0, x0 + 4.0);
  std::snprintf(dt, sizeof dt, "solver.dt=%.10g", factor * kCflStep);
  std::snprintf(end, sizeof end, "solver.end_time=%.10g", kSteps * factor * kCflStep);
  auto s = builtin_simulation<2>("stability_bar.toml", {vertices, dt, end});
  const double e0 = s->state().total();
  try {
    while (!s->finished()) {
      s->step();
      if (s->state().total() > 10.0 * e0) return true;
    }
  } catch (const NumericalError&) {
    return true;  // the growth ran into a failure check first
  }
  return false;
}

//! The smallest unstable factor in [low, high] (low stable, high unstable) to 1e-3.
double critical_factor(double x0, double low, double high) {
  while (high - low > 1e-3) {
    const double mid = 0.5 * (low + high);
    (unstable(x0, mid) ? high : low) = mid;
  }
  return high;
}

}  // namespace

Outcome stability(Resolution) {
  Outcome out;
  const bool centre_bracket = !unstable(0.5, 1.0) && unstable(0.5, 3.0);
  const bool side_bracket = !unstable(0.0001, 0.5) && unstable(0.0001, 3.0);
  out.checks.push_back({"centre case: stable at 1.0 h/c, unstable at 3.0 h/c",
                        centre_bracket ? 1.0 : 0.0, 1.0, 1.0, 1.0, ""});
  out.checks.push_back({"side case: stable at 0.5 h/c, unstable at 3.0 h/c",
                        side_bracket ? 1.0 : 0.0, 1.0, 1.0, 1.0, ""});
  if (!centre_bracket || !side_bracket) return out;
  const double centre = critical_factor(0.5, 1.0, 3.0);
  const double side = critical_factor(0.0001, 0.5, 3.0);
  out.checks.push_back(
      {"points at the cell centres: critical Δt / (h/c)", centre, 2.0, 1.8, 2.2, ""});
  out.checks.push_back({"points beside the nodes: critical Δt / (h/c)", side, 1.0, 0.95, 1.2, ""});
  char table[256];
  std::snprintf(table, sizeof table,
                "| points | critical Δt / (h/c) | analysis (eq 8.41) | thesis runs (Fig 91) |\n"
                "|---|---|---|---|\n| cell centres | %.3f | 2 | 2.0 |\n"
                "| beside the nodes | %.3f | 1 | 1.1 |\n",
                centre, side);
  out.table = table;
  return out;
}

}  // namespace pellicle::validation
