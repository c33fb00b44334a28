// The CFL time step (IJNME eq 19) takes the largest wave speed the materials stage measured
// while it updated the points. Every step must take exactly the step a fresh measurement over
// all points gives (planned_dt), for a gas whose sound speed changes every step, a membrane
// whose density follows its stretch, elastic solids, and after a restart.
#include <gtest/gtest.h>

#include <filesystem>

#include "pellicle/io/checkpoint.hpp"
#include "pellicle/io/restart.hpp"
#include "support/case_text.hpp"

namespace pellicle {
namespace {

template <int D>
void expect_planned_steps(Simulation<D>& s, int steps) {
  for (int k = 0; k < steps; ++k) {
    const double planned = s.planned_dt();
    s.step();
    ASSERT_EQ(s.last_dt(), planned) << "step " << s.step_count();
  }
}

TEST(TimeStep, EachStepTakesTheFreshlyMeasuredCflStep) {
  // Gas expanding into vacuum: the sound speed falls as it expands.
  auto gas = testing::simulation_from_text<2>(testing::case_file("gas_expansion.toml"));
  expect_planned_steps(*gas, 40);
  // Two elastic disks meeting (APIC, quadratic B-splines).
  auto disks =
      testing::simulation_from_text<2>(testing::case_file("two_disks.toml"), {"grid.cell=0.05"});
  expect_planned_steps(*disks, 40);
  // A membrane pendulum.
  auto pendulum = testing::simulation_from_text<2>(testing::case_file("pendulum.toml"));
  expect_planned_steps(*pendulum, 40);
}

TEST(TimeStep, ARestartMeasuresTheWaveSpeedAnew) {
  const std::string text = testing::case_file("gas_expansion.toml");
  const auto source = case_source_from_text(text, "<test case>");
  auto first = testing::simulation_from_text<2>(text);
  first->run(20);
  const auto path = std::filesystem::temp_directory_path() / "pellicle_time_step_restart.h5";
  write_checkpoint<2>(path.string(), *first, checkpoint_header_for(*source));
  // A run restored into the state of the one that ran on (its stored wave speed is stale).
  auto restored = testing::simulation_from_text<2>(text);
  restored->run(5);
  restore_checkpoint<2>(path.string(), *restored);
  std::filesystem::remove(path);
  expect_planned_steps(*restored, 10);
  expect_planned_steps(*first, 10);
  EXPECT_EQ(restored->time(), first->time());
}

}  // namespace
}  // namespace pellicle
