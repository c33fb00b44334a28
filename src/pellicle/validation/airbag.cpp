// Airbag impact (cases/fsi_airbag_inflate.toml, cases/fsi_airbag_impact.toml; thesis §6.3,
// Tables 7–8): the bag is inflated to rest with a tether, then — from that run's checkpoint,
// as `pellicle run … --restart` does — the tether is removed, the gas made inviscid, the velocity
// update FLIP and a probe dropped onto the bag: Cyl-200 (200 mm across, 6.03 kg, 3.90 m/s) and
// Cyl-500 (500 mm, 8.05 kg, 4.70 m/s). The fast variant runs Cyl-200 at 20 mm cells; the full one
// both probes at 20 and 10 mm.
//
// The thesis's displacement histories (Figs 60, 63) were only plotted and the plots are lost,
// so the peak penetration, its time and the rebound speed are reported, not compared. Checked:
// the gas stays in the bag; the probe stops inside the bag and leaves it upwards no faster
// than it came (the bag returns at most the energy it took); the total energy over the impact
// (to the rebound) kept within 3 % of the probe's kinetic energy.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "pellicle/io/checkpoint.hpp"
#include "pellicle/io/restart.hpp"
#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

struct Impactor {
  const char* name;
  double radius, mass, speed, bottom;  // m, kg, m/s, m (the probe's lowest face)
  double grid_radius;                  // the domain's outer radius (the decks')
  int points_per_cell;
};

const Impactor kCyl200{"Cyl-200", 0.1, 6.03, 3.90, 0.329, 0.32, 2};
const Impactor kCyl500{"Cyl-500", 0.25, 8.05, 4.70, 0.315, 0.34, 3};

struct Impact {
  double peak = 0, peak_time = 0, rebound = 0, kinetic = 0;
  //! Total energy change / the probe's kinetic energy: over the impact (to the probe's
  //! fastest upward speed, where the bag lets it go) and over the whole run.
  double impact_energy_change = 0, energy_change = 0;
  double gas_share = 0, membrane_share = 0;  // of the probe's kinetic energy, at the peak
  long most_escaped = 0;
  Series history;
};

Impact impact(const Impactor& probe, double cell, double duration) {
  char text[160];
  std::vector<std::string> grid = {"grid.cell=" + std::to_string(cell)};
  std::snprintf(text, sizeof text, "grid.upper=[%g, 0.499]", probe.grid_radius);
  grid.push_back(text);
  auto inflation = builtin_simulation<2>("fsi_airbag_inflate.toml", grid);
  inflation->run();
  const std::filesystem::path checkpoint =
      std::filesystem::temp_directory_path() /
      ("pellicle_airbag_" + std::string(probe.name) + "_" + std::to_string(cell) + ".h5");
  CheckpointHeader header;
  header.version = PELLICLE_VERSION;
  write_checkpoint(checkpoint.string(), *inflation, header);

  std::vector<std::string> overrides = grid;
  std::snprintf(text, sizeof text, "body[2].region.upper=[%g, %g]", probe.radius,
                probe.bottom + 0.08);
  overrides.push_back(text);
  std::snprintf(text, sizeof text, "body[2].region.lower=[0.0, %g]", probe.bottom);
  overrides.push_back(text);
  overrides.push_back("body[2].total_mass=" + std::to_string(probe.mass));
  overrides.push_back("body[2].velocity=[0.0, " + std::to_string(-probe.speed) + "]");
  overrides.push_back("body[2].points_per_cell=" + std::to_string(probe.points_per_cell));
  overrides.push_back("solver.end_time=" + std::to_string(inflation->time() + duration));
  auto s = builtin_simulation<2>("fsi_airbag_impact.toml", overrides);
  restore_checkpoint<2>(checkpoint.string(), *s);
  std::filesystem::remove(checkpoint);

  const auto& p = s->points();
  const int bag = 0, gas = 1, body = 2;
  auto height = [&] {
    double m = 0, z = 0;
    for (long i = p.bodies[body].begin; i < p.bodies[body].end; ++i)
      m += p.mass[i], z += p.mass[i] * p.position[i].y();
    return z / m;
  };
  auto energies = [&](double& gas_energy, double& membrane_energy) {
    gas_energy = s->material(p.bodies[gas].material)
                     .internal_energy(p, p.bodies[gas].begin, p.bodies[gas].end);
    membrane_energy = s->material(p.bodies[bag].material)
                          .strain_energy(p, p.bodies[bag].begin, p.bodies[bag].end);
  };
  Impact r;
  r.history = {std::string("airbag_") + probe.name + "_" + std::to_string(int(cell * 1000)) + "mm",
               std::string("Airbag, ") + probe.name + ", " + std::to_string(int(cell * 1000)) +
                   " mm cells: probe displacement (m) and velocity / 10 (m/s)",
               {"time (s)", "displacement", "velocity / 10"},
               {}};
  const double start = s->time(), z0 = height(), e0 = s->state().total();
  r.kinetic = 0.5 * probe.mass * probe.speed * probe.speed;
  double gas0, membrane0;
  energies(gas0, membrane0);
  while (!s->finished()) {
    s->step();
    const double drop = z0 - height(), v = body_velocity(*s, body).y();
    r.history.rows.push_back({s->time() - start, drop, v / 10.0});
    if (drop > r.peak) {
      r.peak = drop, r.peak_time = s->time() - start;
      double gas_now, membrane_now;
      energies(gas_now, membrane_now);
      r.gas_share = (gas_now - gas0) / r.kinetic;
      r.membrane_share = (membrane_now - membrane0) / r.kinetic;
    }
    if (v > r.rebound) {
      r.rebound = v;
      r.impact_energy_change = (s->state().total() - e0) / r.kinetic;
    }
    if (s->step_count() % 50 == 0)
      r.most_escaped = std::max(r.most_escaped, escaped_points(p, s->enclosed().at(0)));
  }
  r.energy_change = (s->state().total() - e0) / r.kinetic;
  return r;
}

}  // namespace

Outcome airbag(Resolution resolution) {
  Outcome out;
  out.table =
      "| probe | cell | peak penetration | at | rebound speed | gas / membrane share of the "
      "probe's energy at the peak | energy change / probe energy: to the rebound, to the end "
      "|\n|---|---|---|---|---|---|---|\n";
  std::vector<std::pair<const Impactor*, double>> runs = {{&kCyl200, 0.02}};
  if (resolution == Resolution::full)
    runs = {{&kCyl200, 0.02}, {&kCyl500, 0.02}, {&kCyl200, 0.01}, {&kCyl500, 0.01}};
  for (const auto& [probe, cell] : runs) {
    const Impact r = impact(*probe, cell, 0.1);
    const std::string name =
        std::string(probe->name) + ", " + std::to_string(static_cast<int>(cell * 1000)) + " mm";
    out.checks.push_back(
        {name + ": most gas points outside the bag", double(r.most_escaped), 0, 0, 0, ""});
    out.checks.push_back(
        {name + ": peak penetration (inside the 0.32 m bag)", r.peak, 0.0, 0.0, 0.3, "m"});
    out.checks.push_back({name + ": rebound speed (upwards, at most the impact speed)", r.rebound,
                          probe->speed, 0.0, probe->speed, "m/s"});
    // The impact's energy balance: what the probe brings, the gas and the bag hold or give
    // back (FLIP keeps it to half a percent; APIC's transfers lost 10 % at Cyl-200 and 34 % at
    // Cyl-500 in the gas's sloshing). After the rebound the bag rings on; that part of the run
    // is reported, not checked.
    out.checks.push_back({name + ": energy change over the impact / probe kinetic energy",
                          100.0 * r.impact_energy_change, 0.0, -3.0, 3.0, "%"});
    char row[256];
    std::snprintf(
        row, sizeof row,
        "| %s | %g mm | %.1f mm | %.1f ms | %.2f m/s | %.0f %% / %.0f %% | %+.1f %%, %+.1f %% "
        "|\n",
        probe->name, cell * 1000, r.peak * 1000, r.peak_time * 1000, r.rebound, 100 * r.gas_share,
        100 * r.membrane_share, 100 * r.impact_energy_change, 100 * r.energy_change);
    out.table += row;
    out.series.push_back(r.history);
  }
  return out;
}

}  // namespace pellicle::validation
