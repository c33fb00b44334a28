// Breathing of a spherical membrane (cases/sphere_breathing.toml): started with a uniform
// radial velocity, the mean radial velocity is ∝ cos ωt with ω = sqrt(2E/(ρ(1 − ν)))/R
// (membrane-shell theory; the in-plane plane-stress law of thesis §5.8 on a curved surface).
// The period from its sign changes must be within 2%, the error shrinking with refinement.
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/signals.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

constexpr double R = 1.0, E = 1.0e4, nu = 0.3, rho = 1.0;

double mean_radial_velocity(const Simulation<3>& s) {
  const auto& p = s.points();
  double sum = 0.0, mass = 0.0;
  for (long i = 0; i < p.size(); ++i) {
    sum += p.mass[i] * p.velocity[i].dot(p.position[i].normalized());
    mass += p.mass[i];
  }
  return sum / mass;
}

}  // namespace

Outcome sphere_breathing(Resolution resolution) {
  const double period = 2.0 * std::numbers::pi * R / std::sqrt(2.0 * E / (rho * (1.0 - nu)));
  Outcome out;
  Series series{"sphere_radial_velocity",
                "Sphere breathing: mean radial velocity",
                {"time", "MPM", "analytic"},
                {}};
  std::vector<double> cells{0.2, 0.1};
  if (resolution == Resolution::full) cells.push_back(0.05);
  double previous = std::numeric_limits<double>::infinity();
  for (double cell : cells) {
    char grid[64], skin[200];
    std::snprintf(grid, sizeof grid, "grid.cell=%.10g", cell);
    std::snprintf(skin, sizeof skin,
                  "body[0].membrane={shape=\"sphere\", center=[0.0, 0.0, 0.0], radius=1.0, "
                  "spacing=%.10g, thickness=0.01}",
                  cell / 2);
    auto s = builtin_simulation<3>("sphere_breathing.toml", {grid, skin});
    std::vector<double> t{0.0}, v{mean_radial_velocity(*s)};
    while (!s->finished()) {
      s->step();
      t.push_back(s->time());
      v.push_back(mean_radial_velocity(*s));
      if (cell == cells.back())
        series.rows.push_back(
            {t.back(), v.back(), v[0] * std::cos(2 * std::numbers::pi * t.back() / period)});
    }
    const double error = 100.0 * std::abs(2.0 * slope_per_index(sign_changes(t, v)) / period - 1.0);
    char name[128];
    std::snprintf(name, sizeof name, "period error, cell %g (T = %.5f)", cell, period);
    // Within 2 % on the finest grid, first order above it; every refinement reduces it.
    const double bound = ladder_bound(2.0, cell, cells.back(), previous);
    out.checks.push_back({name, error, 0.0, 0.0, bound, "% (absolute)"});
    previous = error;
  }
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
