// Rigid rotation must produce no stress: a disk set spinning rigidly sees, at every point
// whose stencil lies inside the disk, a velocity gradient that is pure spin (the grid
// reproduces the linear field exactly), so the Jaumann update leaves it unstressed. (That an
// existing stress turns with the body is checked at the material level, in
// unit/test_linear_elastic.cpp.)
#include <gtest/gtest.h>

#include <cmath>

#include "support/case_text.hpp"

namespace pellicle {
namespace {

const std::string kDisk = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.025
boundary = { x_min = "free", x_max = "free", y_min = "free", y_max = "free" }
[solver]
end_time = 0.01
dt = 0.0005
[[material]]
name = "m"
model = "linear-elastic"
density = 1.0
youngs_modulus = 1000.0
poisson_ratio = 0.3
[[body]]
name = "disk"
material = "m"
points_per_cell = 2
angular_velocity = 2.0
center = [0.5, 0.5]
region = { shape = "disk", center = [0.5, 0.5], radius = 0.4 }
)";

// `margin`: distance from the rim, in cells, beyond which the grid sees only the rigid field:
// the edge bias of the first mapping reaches one stencil plus one node support inwards, and
// a PIC-type return (PIC, APIC) carries it one stencil further before the remap.
void check_no_stress_inside(const std::string& kernel, const std::string& update, int margin) {
  auto s = testing::simulation_from_text<2>(
      kDisk, {"solver.kernel=" + kernel, "solver.velocity_update=" + update});
  s->step();
  const auto& p = s->points();
  const double scale =
      1000.0 * 2.0 * s->last_dt();  // E ω Δt: stress a spin would make if read as strain
  int checked = 0;
  for (long i = 0; i < p.size(); ++i) {
    if ((p.position[i] - Vec2(0.5, 0.5)).norm() > 0.4 - margin * s->grid().cell()) continue;
    ++checked;
    EXPECT_LT(p.stress[i].norm(), 1e-10 * scale) << kernel << "/" << update;
  }
  EXPECT_GT(checked, 50);
}

TEST(Rotation, RigidSpinProducesNoStress) {
  check_no_stress_inside("linear", "flip", 3);
  check_no_stress_inside("linear", "pic", 5);
  check_no_stress_inside("quadratic-bspline", "apic", 8);
  check_no_stress_inside("cubic-bspline", "flip", 6);
}

}  // namespace
}  // namespace pellicle
