// Piston–container (thesis §6.1, cases/piston_container.toml): a piston on a spring over a
// column of barotropic liquid. The lowest root of the frequency equation (thesis eq 6.2)
//   ω² m − K − ρ ω c A cot(ωL/c) = 0,   c = sqrt(β/ρ)
// is found by bisection on (0, πc/L), where the left side rises from −∞ to +∞; it must agree
// with Table 3 of the thesis (886.2 and 281.2 rad/s) to 0.1%, and the simulated period
// (from the piston's crossings of its starting height) with it to 2%, for m = 0.1 and 1.0.
// The Tait liquid with K0 = β, linear at this amplitude (strain ~1e-4), must give the same.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/signals.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

constexpr double kLength = 20.0, kArea = 1.0, kDensity = 1e-4, kBulk = 1.58e6, kSpring = 100.0;

double natural_frequency(double mass) {
  const double c = std::sqrt(kBulk / kDensity);
  auto f = [&](double w) {
    return w * w * mass - kSpring - kDensity * w * c * kArea / std::tan(w * kLength / c);
  };
  double lo = 1e-9 * c / kLength, hi = std::numbers::pi * c / kLength * (1.0 - 1e-12);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

Outcome piston_container(Resolution) {
  Outcome out;
  std::string table =
      "| piston mass, liquid | ω analytic (rad/s) | period analytic | period MPM | energy change "
      "|\n"
      "|---|---|---|---|---|\n";
  const double thesis_omega[2] = {886.2, 281.2};
  const double masses[3] = {0.1, 1.0, 0.1};
  const char* liquids[3] = {"barotropic-liquid", "barotropic-liquid", "tait-liquid"};
  for (int k = 0; k < 3; ++k) {
    const double m = masses[k];
    const double omega = natural_frequency(m);
    const double period = 2.0 * std::numbers::pi / omega;
    char mass[64], end[64];
    std::snprintf(mass, sizeof mass, "body[1].point_masses=[[19, %.10g]]", m);
    std::snprintf(end, sizeof end, "solver.end_time=%.10g", 3.2 * period);
    const std::string model = std::string("material[0].model=\"") + liquids[k] + "\"";
    auto s = builtin_simulation<2>("piston_container.toml", {mass, end, model});
    const long piston = s->points().bodies[1].begin + 19;
    const double y0 = s->points().position[piston].y(), e0 = s->state().total();
    std::vector<double> t{0.0}, y{0.0};
    while (!s->finished()) {
      s->step();
      t.push_back(s->time());
      y.push_back(s->points().position[piston].y() - y0);
    }
    // y = −(v0/ω) sin ωt: it changes sign every half period.
    const double measured = 2.0 * slope_per_index(sign_changes(t, y));
    const double energy = 100.0 * (s->state().total() - e0) / e0;
    char name[96], row[160];
    if (k < 2) {
      std::snprintf(name, sizeof name, "ω from eq 6.2, m = %g (thesis Table 3)", m);
      out.checks.push_back({name, omega, thesis_omega[k], 0.999 * thesis_omega[k],
                            1.001 * thesis_omega[k], "rad/s"});
    }
    std::snprintf(name, sizeof name, "period, m = %g, %s", m, liquids[k]);
    out.checks.push_back({name, measured, period, 0.98 * period, 1.02 * period, "s"});
    std::snprintf(row, sizeof row, "| %g, %s | %.2f | %.6f | %.6f | %.3f %% |\n", m, liquids[k],
                  omega, period, measured, energy);
    table += row;
    if (k == 0) {
      Series series{
          "piston_displacement", "Piston displacement, m = 0.1", {"time", "MPM", "exact"}, {}};
      for (std::size_t i = 0; i < t.size(); i += 10)
        series.rows.push_back({t[i], y[i], -std::sin(omega * t[i]) / omega});
      out.series.push_back(std::move(series));
    }
  }
  out.table = table;
  return out;
}

}  // namespace pellicle::validation
