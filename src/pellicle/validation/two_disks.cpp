// Two elastic disks (cases/two_disks.toml; Sulsky, Chen & Schreyer 1994): E = 1000, ν = 0.3,
// ρ = 1000, v = ±(0.1, 0.1). They touch near t = 1.6 and rebound. With APIC and quadratic
// B-splines, the total energy after the collision must be within 2% of the initial energy;
// momentum (zero) must stay zero; the disks must separate with reversed velocities. The
// FLIP/PIC blend is recorded beside it.
#include <cmath>
#include <cstdio>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

struct Collision {
  double energy_after, energy_min, momentum;
  Vec2 lower_velocity;
};

Collision collide(const std::vector<std::string>& overrides, Series* series) {
  auto s = builtin_simulation<2>("two_disks.toml", overrides);
  const double e0 = s->state().total();
  double e_min = 1.0, momentum = 0.0;
  long step = 0;
  while (!s->finished()) {
    s->step();
    const auto st = s->state();
    e_min = std::min(e_min, st.total() / e0);
    momentum = std::max(momentum, st.momentum.norm());
    if (series && ++step % 5 == 0)
      series->rows.push_back({s->time(), st.kinetic / e0, st.strain / e0, st.total() / e0});
  }
  return {s->state().total() / e0, e_min, momentum, body_velocity(*s, 0)};
}

}  // namespace

Outcome two_disks(Resolution resolution) {
  Outcome out;
  const std::string cell = resolution == Resolution::full ? "0.003125" : "0.00625";
  Series series{"two_disks_energy",
                "Two disks, APIC: energies / initial energy",
                {"time", "kinetic", "strain", "total"},
                {}};
  const Collision apic = collide({"grid.cell=" + cell}, &series);
  out.checks.push_back({"APIC, quadratic B-spline, h = " + cell + ": E(end)/E(0)",
                        apic.energy_after, 1.0, 0.98, 1.02, ""});
  out.checks.push_back(
      {"APIC: min E(t)/E(0) while the disks press together", apic.energy_min, 1.0, 0.94, 1.02, ""});
  out.checks.push_back(
      {"APIC: largest |total momentum|", apic.momentum, 0.0, 0.0, 1e-10, "kg m/s"});
  out.checks.push_back({"APIC: lower disk x-velocity after the rebound", apic.lower_velocity.x(),
                        -0.1, -0.11, -0.08, "m/s"});
  // The seeds' kernel with a 99% FLIP blend: the PIC share dissipates. This problem is not
  // in the seeds (Sulsky, Chen & Schreyer 1994 plot energies of pure FLIP only), so the 8 %
  // bound guards against a regression; the APIC checks above carry the physics.
  const Collision blend = collide({"solver.kernel=linear", "solver.velocity_update=blend",
                                   "solver.flip_fraction=0.99", "grid.cell=0.0125"},
                                  nullptr);
  out.checks.push_back({"FLIP/PIC blend 0.99, linear, h = 0.0125: E(end)/E(0)", blend.energy_after,
                        1.0, 0.92, 1.02, ""});
  out.checks.push_back({"blend: lower disk x-velocity after the rebound", blend.lower_velocity.x(),
                        -0.1, -0.11, -0.08, "m/s"});
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
