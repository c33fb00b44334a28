// Two-bar impact with York's contact-release (IJNME §4.2, Fig. 20; thesis A.1.5, deck
// A.4.12; cases/two_bars_stick.toml with [contact] model = "release"), on the deck's grid of
// cells 0.25 and two refinements (Δt ∝ h; at the deck's Δt = 7e-4, CFL 0.93, the energy
// grows, see docs/validation). The paper reports centre-of-mass velocities after impact of
// about 0.3 (left) and 1.7 (right) with an 11% energy loss it attributes to its release
// algorithm, and a velocity difference that grows under refinement and converges.
// Checked: the bars part (difference > 1.5, against 0 when they stick), the difference
// converges (each change smaller than the one before), momentum is conserved, and the
// largest energy gain during the impact falls with refinement, to within 2% on the finest
// grid. The paper's 0.3 and 1.7 are reported, not met: see docs/validation.
#include <cmath>
#include <cstdio>
#include <limits>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {

Outcome two_bars_release(Resolution) {
  Outcome out;
  std::string table =
      "| cell | left bar after | right bar after | difference | energy after / before |\n"
      "|---|---|---|---|---|\n";
  Series series{"two_bars_release_velocity",
                "Two-bar impact with contact-release: centre-of-mass velocities (IJNME Fig. 20b)",
                {"time", "left bar", "right bar"},
                {{0.0, 2.0, 0.0}}};
  std::vector<double> differences;
  double previous_gain = std::numeric_limits<double>::infinity();
  for (double cell : {0.25, 0.125, 0.0625}) {
    char grid[64], dt[64];
    std::snprintf(grid, sizeof grid, "grid.cell=%g", cell);
    std::snprintf(dt, sizeof dt, "solver.dt=%g", 2e-4 * cell / 0.25);
    auto s = builtin_simulation<2>("two_bars_stick.toml",
                                   {grid, dt, "contact={model=\"release\", criterion=\"both\"}"});
    const double e0 = s->state().total(), momentum0 = s->state().momentum.x();
    double momentum_error = 0.0, largest_energy = e0;
    while (!s->finished()) {
      s->step();
      const auto state = s->state();
      momentum_error = std::max(momentum_error, std::abs(state.momentum.x() / momentum0 - 1.0));
      largest_energy = std::max(largest_energy, state.total());
      if (cell == 0.25)
        series.rows.push_back({s->time(), body_velocity(*s, 0).x(), body_velocity(*s, 1).x()});
    }
    const double left = body_velocity(*s, 0).x(), right = body_velocity(*s, 1).x();
    differences.push_back(right - left);
    char name[96], row[160];
    std::snprintf(row, sizeof row, "| %g | %.4f | %.4f | %.4f | %.4f |\n", cell, left, right,
                  right - left, s->state().total() / e0);
    table += row;
    std::snprintf(name, sizeof name, "velocity difference after impact, cell %g", cell);
    out.checks.push_back({name, right - left, 2.0, 1.5, 2.0, ""});
    const double gain = 100.0 * (largest_energy / e0 - 1.0);
    std::snprintf(name, sizeof name, "largest energy gain during the impact, cell %g", cell);
    // At most 2 % at cell 0.0625, first order above it; every refinement reduces it.
    out.checks.push_back(
        {name, gain, 0.0, 0.0, ladder_bound(2.0, cell, 0.0625, previous_gain), "%"});
    previous_gain = gain;
    std::snprintf(name, sizeof name, "relative change of momentum, cell %g", cell);
    out.checks.push_back({name, momentum_error, 0.0, 0.0, 1e-9, ""});
  }
  const double first = std::abs(differences[1] - differences[0]);
  const double second = std::abs(differences[2] - differences[1]);
  out.checks.push_back(
      {"change of the difference, 0.125 → 0.0625 (vs 0.25 → 0.125)", second, 0.0, 0.0, first, ""});
  out.table = table;
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
