// Dog-bone membrane expansion (cases/fsi_dogbone_thesis_1.toml; thesis §6.2, Fig 47,
// Tables 4–6): gas at p = 100 fills an unstressed dog-bone membrane (a quarter, symmetry on
// x = 0 and y = 0); the gas viscosity damps the ringing until the membrane is a circle whose
// tension balances the pressure. Simulations 1–4 refine the cell 0.4 → 0.05 with 56 → 400
// membrane points, 64 gas points per cell, linear kernel, FLIP and MUSL as the thesis. The
// fast variant runs simulations 1 and 2.
//
// Checked: no gas point ever outside the membrane; total energy kept within 5 % (the thesis
// lost 3.6 % and 3.4 % in simulations 1 and 2); from simulation 2 on, tension = p R at the
// end within 10 %, no worse than the thesis (its hoop stress was 7–12 % above p r / t,
// Table 6); the final radii at 0° and 90° of the finest run (simulation 4, --full) within 2 %
// of the thesis's and circular within 2 %. Simulations 2–3 are held to 5 % of the thesis's
// radii at the same cell and the fast variant's last (simulation 2) to 3 % out of round: the
// radius is set by the length of membrane the circle takes up (its strain is 0.04 %), and at
// coarse cells the folds of the first swing keep some of it (the one-way law keeps a crushed
// point's compressive strain, and the grid cannot stretch one point of a cell without its taut
// neighbours), more or less by round-off; the table's length column shows how much. The
// thesis's radii grow with refinement for the same reason. Simulation 1 (cell 0.4, four cells
// across) keeps slack folds whose final state is not unique (round-off moves its end radii by
// 8 %), so its shape is reported, not checked. Its crushed points (the one-way law keeps their
// compressive strain near −1, so they carry no stress) rattle at up to 30 m/s among the gas;
// one that reaches the gas's edge has nodes of its own and coasts on, and leaves the grid
// (cell 0.4, one run in the five orders of summation tried, at t = 4.67). Simulation 1 then
// reports where it stopped, and its checks cover the run up to there. The final pressures are
// reported beside the thesis's (Table 5): the thesis's are grid averages that read low
// (docs/theory/fsi-problems.md §2.5). Figures: docs/validation/README.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "pellicle/core/error.hpp"
#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

struct Refinement {
  int number;
  double cell;
  int points;
  double dt;
  bool cell_density;  //!< the gas's density from the quadratic cell density (thesis eq 4.6)
  double radius_0, radius_90, pressure;  // Table 5
};

// Δt: 0.56 of the membrane's c Δt / h for simulation 1 (the case file's), 0.9 of it from
// simulation 2 on (the thesis's deck for simulation 4 runs at 0.94). Simulations 3 and 4 take
// the gas density from the cells: with the continuity update a gas point left alone in a gap
// between the lines FLIP gas forms expands without bound (to ρ = 0.0016 at t = 1.73 in
// simulation 3, at t = 0.25 in simulation 4) until the viscous step limit stops the run;
// the cell density gives it its neighbourhood's.
const Refinement kSimulations[] = {{1, 0.4, 56, 1.4e-4, false, 1.08, 1.13, 33.4},
                                   {2, 0.2, 100, 1.2e-4, false, 1.335, 1.334, 24.9},
                                   {3, 0.1, 200, 0.6e-4, true, 1.388, 1.387, 27.0},
                                   {4, 0.05, 400, 0.3e-4, true, 1.394, 1.396, 29.0}};

struct Result {
  double radius_0 = 0, radius_90 = 0, pressure = 0, balance = 0, energy_change = 0;
  double length_ratio = 0;  //!< the membrane polyline's final length / initial
  std::string stopped;      //!< simulation 1 only: the numerical failure that ended it early
  long most_escaped = 0;
  Series history;
};

Result expand(const Refinement& sim) {
  // The gas keeps 0.05 clear of the membrane at every cell, as the thesis's deck.
  std::vector<std::string> overrides = {"grid.cell=" + std::to_string(sim.cell),
                                        "solver.dt=" + std::to_string(sim.dt),
                                        "body[0].membrane.points=" + std::to_string(sim.points),
                                        "body[1].region.gap=" + std::to_string(0.05 / sim.cell)};
  if (sim.cell_density) overrides.push_back("material[0].density_update=cell-quadratic");
  auto s = builtin_simulation<2>("fsi_dogbone_thesis_1.toml", overrides);
  const auto& p = s->points();
  const auto& skin = p.bodies[0];
  const auto& gas = p.bodies[1];
  const auto& pair = s->enclosed().at(0);
  auto gas_pressure = [&] {
    std::vector<double> values;
    s->material(gas.material).history_values(p, gas.begin, gas.end, values);
    return values.at(0);
  };
  Result r;
  r.history = {"dogbone_" + std::to_string(sim.number),
               "Dog-bone, simulation " + std::to_string(sim.number) + ": radii and pressure / 100",
               {"time", "radius at 0°", "radius at 90°", "pressure / 100"},
               {}};
  auto length = [&] {
    double sum = 0.0;
    for (long i = skin.begin + 1; i < skin.end; ++i)
      sum += (p.position[i] - p.position[i - 1]).norm();
    return sum;
  };
  const double initial_length = length();
  const double e0 = s->state().total();
  double e_last = e0;  // at the last sample
  double next = 0.0;
  try {
    while (!s->finished()) {
      s->step();
      if (s->time() + 1e-12 < next) continue;
      next += 0.02;
      r.most_escaped = std::max(r.most_escaped, escaped_points(p, pair));
      r.history.rows.push_back({s->time(), p.position[skin.begin].x(), p.position[skin.end - 1].y(),
                                gas_pressure() / 100.0});
      e_last = s->state().total();
    }
  } catch (const NumericalError& failure) {
    if (sim.number != 1) throw;  // only the coarsest run's crushed points may leave the grid
    r.stopped = failure.what();
  }
  r.radius_0 = p.position[skin.begin].x();
  r.radius_90 = p.position[skin.end - 1].y();
  r.pressure = gas_pressure();
  const double radius =
      std::sqrt(4.0 * enclosed_volume(p, pair, Kinematics::plane_strain) / std::numbers::pi);
  r.balance = mean_tension(p, pair) / (r.pressure * radius);
  r.energy_change = (r.stopped.empty() ? s->state().total() : e_last) / e0 - 1.0;
  r.length_ratio = length() / initial_length;
  return r;
}

}  // namespace

Outcome dogbone(Resolution resolution) {
  Outcome out;
  const int count = resolution == Resolution::full ? 4 : 2;
  out.table =
      "| simulation | cell | membrane points | radius 0° / 90° (thesis) | pressure (thesis) | "
      "tension / p R | energy change | membrane length / initial |\n"
      "|---|---|---|---|---|---|---|---|\n";
  std::string stops;  // after the table
  for (int k = 0; k < count; ++k) {
    const Refinement& sim = kSimulations[k];
    const Result r = expand(sim);
    const std::string name = "simulation " + std::to_string(sim.number);
    out.checks.push_back({name + ": most gas points outside the membrane",
                          static_cast<double>(r.most_escaped), 0.0, 0.0, 0.0, ""});
    out.checks.push_back(
        {name + ": total energy change", 100.0 * r.energy_change, 0.0, -5.0, 5.0, "%"});
    if (sim.number > 1) {  // simulation 1 keeps folds whose final state is not unique
      out.checks.push_back({name + ": tension / (p R)", r.balance, 1.0, 0.9, 1.1, ""});
      const double band = sim.number == 4 ? 0.02 : 0.05;
      out.checks.push_back({name + ": final radius at 0°", r.radius_0, sim.radius_0,
                            (1.0 - band) * sim.radius_0, (1.0 + band) * sim.radius_0, ""});
      out.checks.push_back({name + ": final radius at 90°", r.radius_90, sim.radius_90,
                            (1.0 - band) * sim.radius_90, (1.0 + band) * sim.radius_90, ""});
    }
    if (k == count - 1)
      out.checks.push_back(
          {name + ": out of round |r0 − r90| / mean",
           100.0 * std::abs(r.radius_0 - r.radius_90) / (0.5 * (r.radius_0 + r.radius_90)), 0.0,
           0.0, sim.number == 4 ? 2.0 : 3.0, "%"});
    char row[256];
    std::snprintf(row, sizeof row,
                  "| %d | %g | %d | %.3f / %.3f (%.3f / %.3f) | %.1f (%.1f) | "
                  "%.3f | %+.2f %% | %.3f |\n",
                  sim.number, sim.cell, sim.points, r.radius_0, r.radius_90, sim.radius_0,
                  sim.radius_90, r.pressure, sim.pressure, r.balance, 100.0 * r.energy_change,
                  r.length_ratio);
    out.table += row;
    if (!r.stopped.empty()) stops += "\n" + name + " stopped early: " + r.stopped + "\n";
    out.series.push_back(r.history);
  }
  out.table += stops;
  return out;
}

}  // namespace pellicle::validation
