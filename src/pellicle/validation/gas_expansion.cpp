// Gas expansion into vacuum (thesis §4.2, cases/gas_expansion.toml): an inviscid quarter
// cylinder of gas with no artificial viscosity, so kinetic plus internal energy must be
// conserved — within 1% at t = 0.005, the error falling with Δt. The gas edge must have
// moved out, and no faster than the escape speed 2c/(γ − 1) of a gas into vacuum. Point
// positions, pressure and energy at t = 0.005 are plotted as in thesis Figures 16–18.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

constexpr double kGamma = 1.4, kEnergy = 250.0;
const Vec2 kCentre(0.5, 0.5);

double edge_radius(const Simulation<2>& s) {
  double edge = 0.0;
  for (const auto& x : s.points().position) edge = std::max(edge, (x - kCentre).norm());
  return edge;
}

struct Expansion {
  double energy_change = 0.0;           //!< relative, %
  double start_edge = 0.0, edge = 0.0;  //!< largest point distance from the axis
  std::unique_ptr<Simulation<2>> simulation;
};

Expansion expand(double cfl) {
  Expansion out;
  out.simulation =
      builtin_simulation<2>("gas_expansion.toml", {"solver.cfl=" + std::to_string(cfl)});
  auto& s = *out.simulation;
  const double e0 = s.state().total();
  out.start_edge = edge_radius(s);
  s.run();
  out.energy_change = 100.0 * (s.state().total() - e0) / e0;
  out.edge = edge_radius(s);
  return out;
}

}  // namespace

Outcome gas_expansion(Resolution) {
  Outcome out;
  const double c = std::sqrt(kGamma * (kGamma - 1.0) * kEnergy);
  std::string table = "| CFL number | energy change (%) | edge radius |\n|---|---|---|\n";
  double previous = std::numeric_limits<double>::infinity();
  for (double cfl : {0.4, 0.2, 0.1}) {
    const Expansion run = expand(cfl);
    char row[128];
    std::snprintf(row, sizeof row, "| %.2f | %.4f | %.4f |\n", cfl, run.energy_change, run.edge);
    table += row;
    char name[96];
    std::snprintf(name, sizeof name, "|energy change|, CFL %.2f", cfl);
    // Within 1 % at CFL 0.1; the explicit step's energy error is at least first order in Δt.
    out.checks.push_back(
        {name, std::abs(run.energy_change), 0.0, 0.0, ladder_bound(1.0, cfl, 0.1, previous), "%"});
    previous = std::abs(run.energy_change);
    if (cfl != 0.1) continue;
    const double t = run.simulation->time();
    out.checks.push_back({"edge radius at t = 0.005 (initial edge as reference)", run.edge,
                          run.start_edge, run.start_edge * (1.0 + 1e-6),
                          run.start_edge + 2.0 * c / (kGamma - 1.0) * t, ""});
    Series points{"points_t0.005",
                  "Gas expansion, t = 0.005: points coloured by pressure and internal energy",
                  {"x", "y", "pressure", "internal energy"},
                  {}};
    const auto& p = run.simulation->points();
    const auto& energy = p.named<double>("internal_energy");
    for (long i = 0; i < p.size(); ++i)
      points.rows.push_back({p.position[i].x(), p.position[i].y(),
                             (kGamma - 1.0) * p.density[i] * energy[i], energy[i]});
    out.series.push_back(std::move(points));
  }
  out.table = table;
  return out;
}

}  // namespace pellicle::validation
