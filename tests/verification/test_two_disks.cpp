// Two elastic disks of Sulsky, Chen and Schreyer (1994) (cases/two_disks.toml): E = 1000,
// ν = 0.3, ρ = 1000, v = ±(0.1, 0.1). They collide near t = 1.6 and rebound. Energy must be
// conserved within 2% through the collision, momentum exactly, and the disks must separate
// with reversed velocities.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/case_text.hpp"

namespace pellicle {
namespace {

struct Outcome {
  double energy_after;  // E(t_end)/E(0)
  double energy_min;    // min_t E(t)/E(0): the dip while the disks are pressed together
  double momentum_error;
  Vec2 lower_velocity, upper_velocity;
};

Outcome collide(const std::vector<std::string>& overrides) {
  auto s = testing::simulation_from_text<2>(testing::case_file("two_disks.toml"), overrides);
  const double e0 = s->state().total();
  double e_min = 1.0, momentum_error = 0.0;
  while (!s->finished()) {
    s->step();
    const auto state = s->state();
    e_min = std::min(e_min, state.total() / e0);
    momentum_error = std::max(momentum_error, state.momentum.norm());
  }
  return {s->state().total() / e0, e_min, momentum_error, testing::body_velocity(*s, 0),
          testing::body_velocity(*s, 1)};
}

TEST(TwoDisks, ApicConservesEnergyThroughTheCollision) {
  // Quadratic B-splines, 160 × 160 cells: about 51,000 points.
  const Outcome o = collide({"grid.cell=0.00625"});
  std::printf("two disks, APIC: E_end/E_0 = %.4f, min E/E_0 = %.4f, v_lower = (%.4f, %.4f)\n",
              o.energy_after, o.energy_min, o.lower_velocity.x(), o.lower_velocity.y());
  EXPECT_NEAR(o.energy_after, 1.0, 0.02);  // measured 0.985
  EXPECT_GT(o.energy_min, 0.94);           // measured 0.954 at peak compression
  EXPECT_LT(o.momentum_error, 1e-10);      // total momentum is zero and stays zero
  // Rebound: the lower disk, launched at (+0.1, +0.1), moves back down-left.
  EXPECT_LT(o.lower_velocity.x(), -0.08);
  EXPECT_LT(o.lower_velocity.y(), -0.08);
  EXPECT_GT(o.upper_velocity.x(), 0.08);
}

TEST(TwoDisks, FlipPicBlendRebounds) {
  // The seeds' kernel with a 99% FLIP blend: the disks rebound; PIC's share damps energy.
  const Outcome o = collide({"solver.kernel=linear", "solver.velocity_update=blend",
                             "solver.flip_fraction=0.99"});
  std::printf("two disks, blend 0.99: E_end/E_0 = %.4f, min E/E_0 = %.4f\n", o.energy_after,
              o.energy_min);
  // Regression guard, not the 2% goal: the PIC share dissipates 6.6% over the 540 steps of
  // this run (measured 0.934); APIC above meets the 2%.
  EXPECT_GT(o.energy_after, 0.92);
  EXPECT_LT(o.lower_velocity.x(), -0.08);
  EXPECT_LT(o.momentum_error, 1e-10);
}

}  // namespace
}  // namespace pellicle
