// Boundary conditions from [[boundary]] tables: a bar clamped at one end and pulled at the
// other by prescribed-velocity boxes; the points between the grip's nodes move exactly with
// it, and after `until` the grip lets go.
#include <gtest/gtest.h>

#include "support/case_text.hpp"

namespace pellicle {
namespace {

const char* kBar = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.2, 0.2]
cell = 0.05
boundary = { x_min = "free", x_max = "free", y_min = "slip", y_max = "slip" }
[solver]
end_time = 0.5
dt = 1e-3
[[material]]
name = "rubber"
model = "linear-elastic"
density = 1000.0
youngs_modulus = 1.0e5
poisson_ratio = 0.3
[[body]]
name = "bar"
material = "rubber"
region = { shape = "box", lower = [0.05, 0.0], upper = [1.05, 0.2] }
[[boundary]]
model = "prescribed-velocity"
lower = [0.0, 0.0]
upper = [0.15, 0.2]
velocity = [0.0, 0.0]
[[boundary]]
model = "prescribed-velocity"
lower = [0.9, 0.0]
upper = [1.2, 0.2]
velocity = [0.02, 0.0]
)";

TEST(Boundary, PrescribedVelocityMovesThePointsBetweenItsNodes) {
  auto s = testing::simulation_from_text<2>(kBar);
  const auto start = s->points().position;
  s->run();
  const auto& p = s->points();
  const double h = 0.05, t = s->time();
  int gripped = 0, clamped = 0;
  for (long i = 0; i < p.size(); ++i) {
    // Linear kernel: a point moves with the two nodes of its cell, both inside the box.
    const double x0 = start[i].x();
    const Vec2 moved = p.position[i] - start[i];
    if (x0 > 0.9 + h * 1e-6 && x0 < 1.05) {
      ++gripped;
      EXPECT_NEAR(moved.x(), 0.02 * t, 1e-12) << "point " << i;  // round-off of Σ Δt v
      EXPECT_NEAR(moved.y(), 0.0, 1e-14);
    }
    if (x0 < 0.1) {
      ++clamped;
      EXPECT_NEAR(moved.norm(), 0.0, 1e-14) << "point " << i;
    }
  }
  EXPECT_GT(gripped, 0);
  EXPECT_GT(clamped, 0);
  // The bar between is stretched: tension in the middle.
  double sxx = 0.0;
  int middle = 0;
  for (long i = 0; i < p.size(); ++i)
    if (std::abs(start[i].x() - 0.55) < 0.1) sxx += p.stress[i][0], ++middle;
  EXPECT_GT(sxx / middle, 0.0);
}

TEST(Boundary, PrescribedVelocityLetsGoAfterUntil) {
  auto s = testing::simulation_from_text<2>(kBar, {"boundary[1].until=0.25"});
  s->run();
  const auto& p = s->points();
  double largest_difference = 0.0;
  for (long i = 0; i < p.size(); ++i)
    if (p.position[i].x() > 1.0)
      largest_difference = std::max(largest_difference, std::abs(p.velocity[i].x() - 0.02));
  EXPECT_GT(largest_difference, 1e-4);  // the stretched bar pulls the released end back
}

TEST(Boundary, UnknownModelAndBadBoxAreRejected) {
  EXPECT_THROW(testing::simulation_from_text<2>(kBar, {"boundary[0].model=glue"}), InputError);
  EXPECT_THROW(testing::simulation_from_text<2>(kBar, {"boundary[0].upper=[-1.0, 0.2]"}),
               InputError);
  EXPECT_THROW(testing::simulation_from_text<2>(kBar, {"boundary[0].velocity=[1.0]"}), InputError);
}

// A quarter of a gas-filled circular membrane (Sulsky & York 2000 §8, example 1): its end
// points lie on the symmetry faces and must slide in them, never leave them.
const char* kQuarter = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.1
boundary = { x_min = "slip", x_max = "free", y_min = "slip", y_max = "free" }
[solver]
end_time = 0.05
dt = 0.7e-4
velocity_update = "apic"
kernel = "quadratic-bspline"
[[material]]
name = "skin"
model = "membrane"
density = 0.5
youngs_modulus = 1.0e6
poisson_ratio = 0.3
[[material]]
name = "air"
model = "gas"
density = 1.0
gamma = 1.4
viscosity = 0.2
[[body]]
name = "skin"
material = "skin"
membrane = { shape = "circle", center = [0.0, 0.0], radius = 0.5, start_angle = 0, end_angle = 90, points = 91, thickness = 0.1 }
[[body]]
name = "gas"
material = "air"
points_per_cell = 2
internal_energy = 2500.0
region = { shape = "disk", center = [0.0, 0.0], radius = 0.47 }
)";

TEST(Boundary, MembraneEndsOnSymmetryFacesSlideInThem) {
  auto s = testing::simulation_from_text<2>(kQuarter);
  s->run();
  EXPECT_EQ(s->step_count(), 715);
  const auto& p = s->points();
  const auto& skin = p.bodies[0];
  const Vec2 first = p.position[skin.begin], last = p.position[skin.end - 1];
  // On the faces to round-off (the arc's end is generated at 0.5 cos 90° = 3e-17).
  EXPECT_LT(std::abs(first.y()), 1e-12);
  EXPECT_LT(std::abs(last.x()), 1e-12);
  // Inflated by the gas (p ≈ 940): the hoop strain p R/(E t) ≈ 4.7e-3 stretches the radius
  // by about 2.3e-3 while the membrane rings about that; the ends slid out along the faces.
  EXPECT_GT(first.x(), 0.5);
  EXPECT_GT(last.y(), 0.5);
  EXPECT_NEAR(first.x(), last.y(), 1e-9);  // the two ends move alike (symmetry)
}

}  // namespace
}  // namespace pellicle
