// Patch tests: states the discretisation must reproduce exactly.
// 1. Uniaxial stress: a block prestressed with σ_xx = s between two frictionless walls is
//    in equilibrium; it must stay at rest with its stress unchanged.
// 2. Uniform stretching: a velocity field linear in x gives, at every point whose stencil
//    lies inside the body, exactly the strain increment a Δt and the matching stress.
#include <gtest/gtest.h>

#include <cmath>

#include "support/case_text.hpp"

namespace pellicle {
namespace {

const std::string kBlock = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.1
kinematics = "plane-stress"
boundary = { x_min = "slip", x_max = "slip", y_min = "free", y_max = "free" }
[solver]
end_time = 0.05
dt = 0.0005
[[material]]
name = "m"
model = "linear-elastic"
density = 1.0
youngs_modulus = 1000.0
poisson_ratio = 0.25
[[body]]
name = "block"
material = "m"
points_per_cell = 2
region = { shape = "box", lower = [0.0, 0.3], upper = [1.0, 0.7] }
)";

void check_uniaxial_equilibrium(const std::string& kernel) {
  const double s0 = 10.0;
  auto s = testing::simulation_from_text<2>(
      kBlock, {"solver.kernel=" + kernel, "body[0].initial_stress={xx=10.0}"});
  s->run();
  EXPECT_EQ(s->step_count(), 100);
  const auto& p = s->points();
  double max_speed = 0.0, max_stress_error = 0.0;
  for (long i = 0; i < p.size(); ++i) {
    max_speed = std::max(max_speed, p.velocity[i].norm());
    Sym<2> expected = Sym<2>::Zero();
    expected[0] = s0;
    max_stress_error = std::max(max_stress_error, (p.stress[i] - expected).norm());
  }
  EXPECT_LT(max_speed, 1e-12) << kernel;
  EXPECT_LT(max_stress_error, 1e-10 * s0) << kernel;
}

TEST(Patch, UniaxialStressBetweenWallsStaysInEquilibriumLinear) {
  check_uniaxial_equilibrium("linear");
}
TEST(Patch, UniaxialStressBetweenWallsStaysInEquilibriumGimp) {
  check_uniaxial_equilibrium("ugimp");
}
// The B-splines reach past the walls; the mirrored ghost nodes complete their stencils.
TEST(Patch, UniaxialStressBetweenWallsStaysInEquilibriumBSplines) {
  check_uniaxial_equilibrium("quadratic-bspline");
  check_uniaxial_equilibrium("cubic-bspline");
}

void check_uniform_stretching(const std::string& kernel, int margin_cells) {
  const double a = 0.01;
  auto s = testing::simulation_from_text<2>(
      kBlock, {"solver.kernel=" + kernel, "grid.cell=0.05",
               "body[0].velocity_gradient=[[0.01, 0.0], [0.0, 0.0]]",
               "body[0].region={shape=\"box\", lower=[0.2, 0.2], upper=[0.8, 0.8]}"});
  s->step();
  const auto& p = s->points();
  const auto& strain = p.named<Sym<2>>("strain");
  const double dt = s->last_dt(), h = s->grid().cell();
  const double E = 1000.0, nu = 0.25, c = E / (1 - nu * nu);
  int checked = 0;
  for (long i = 0; i < p.size(); ++i) {
    const Vec2 x = p.position[i];
    const double inside = std::min({x.x() - 0.2, 0.8 - x.x(), x.y() - 0.2, 0.8 - x.y()});
    if (inside < margin_cells * h) continue;
    ++checked;
    EXPECT_NEAR(strain[i][0], a * dt, 1e-12 * a * dt) << kernel << " at " << x.transpose();
    EXPECT_NEAR(strain[i][1], 0.0, 1e-12 * a * dt);
    EXPECT_NEAR(strain[i][3], 0.0, 1e-12 * a * dt);
    EXPECT_NEAR(p.stress[i][0], c * a * dt, 1e-10 * c * a * dt);  // plane stress
    EXPECT_NEAR(p.stress[i][1], nu * c * a * dt, 1e-10 * c * a * dt);
  }
  EXPECT_GT(checked, 0);
}

TEST(Patch, UniformStretchingIsExactInside) {
  // Margin: the farthest stencil node plus that node's support, in cells.
  check_uniform_stretching("linear", 2);
  check_uniform_stretching("ugimp", 3);
  check_uniform_stretching("quadratic-bspline", 3);
  check_uniform_stretching("cubic-bspline", 4);
}

}  // namespace
}  // namespace pellicle
