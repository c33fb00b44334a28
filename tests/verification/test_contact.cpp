// Contact in 3D (the validation problems are 2D): a block sliding on a rigid plate under
// gravity tilted by 30° accelerates at g (sin θ − μ cos θ) within 3%, and two blocks
// colliding head-on with contact-release part, conserving momentum.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/case_text.hpp"

namespace pellicle {
namespace {

const std::string kBlockOnPlate = R"(
[grid]
lower = [0.0, 0.0, 0.0]
upper = [2.0, 0.6, 0.6]
cell = 0.1
boundary = { x_min = "fixed", x_max = "fixed", y_min = "fixed", y_max = "fixed", z_min = "fixed", z_max = "fixed" }
[solver]
end_time = 0.6
cfl = 0.4
gravity = [4.905, 0.0, -8.49571]
[contact]
model = "friction"
coefficient = 0.3
[[material]]
name = "plate"
model = "rigid"
density = 1000.0
[[material]]
name = "rubber"
model = "linear-elastic"
density = 1000.0
youngs_modulus = 1.0e6
poisson_ratio = 0.3
[[body]]
name = "plate"
material = "plate"
region = { shape = "box", lower = [0.0, 0.0, 0.1], upper = [2.0, 0.6, 0.2] }
[[body]]
name = "block"
material = "rubber"
region = { shape = "box", lower = [0.3, 0.2, 0.2], upper = [0.5, 0.4, 0.4] }
)";

TEST(Contact, BlockSlidesOnAPlateIn3DWithCoulombFriction) {
  auto s = testing::simulation_from_text<3>(kBlockOnPlate);
  std::vector<double> t, v;
  while (!s->finished()) {
    s->step();
    if (s->time() < 0.2) continue;
    t.push_back(s->time());
    v.push_back(
        testing::body_mean(s->points(), 1, [&](long p) { return s->points().velocity[p].x(); }));
  }
  // Least-squares slope of v(t).
  double st = 0, sv = 0, stt = 0, stv = 0;
  const double n = static_cast<double>(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    st += t[i], sv += v[i], stt += t[i] * t[i], stv += t[i] * v[i];
  }
  const double a = (n * stv - st * sv) / (n * stt - st * st);
  const double exact = 9.81 * (0.5 - 0.3 * std::cos(std::numbers::pi / 6));
  EXPECT_NEAR(a, exact, 0.03 * exact);
}

const std::string kTwoBlocks = R"(
[grid]
lower = [0.0, 0.0, 0.0]
upper = [2.0, 0.6, 0.6]
cell = 0.1
boundary = { x_min = "slip", x_max = "slip", y_min = "slip", y_max = "slip", z_min = "slip", z_max = "slip" }
[solver]
end_time = 0.25
cfl = 0.4
[contact]
model = "release"
[[material]]
name = "m"
model = "linear-elastic"
density = 1.0
youngs_modulus = 100.0
poisson_ratio = 0.0
[[body]]
name = "left"
material = "m"
velocity = [1.0, 0.0, 0.0]
region = { shape = "box", lower = [0.4, 0.1, 0.1], upper = [0.8, 0.5, 0.5] }
[[body]]
name = "right"
material = "m"
region = { shape = "box", lower = [1.0, 0.1, 0.1], upper = [1.4, 0.5, 0.5] }
)";

TEST(Contact, BlocksCollidingIn3DPartWithRelease) {
  auto s = testing::simulation_from_text<3>(kTwoBlocks);
  const double momentum = s->state().momentum.x();
  s->run();
  auto mean_vx = [&](int body) {
    return testing::body_mean(s->points(), body,
                              [&](long p) { return s->points().velocity[p].x(); });
  };
  // Equal blocks: an elastic exchange leaves about 0 and 1; sticking would leave ½ and ½.
  EXPECT_LT(mean_vx(0), 0.25);
  EXPECT_GT(mean_vx(1), 0.75);
  EXPECT_NEAR(s->state().momentum.x(), momentum, 1e-12);
}

}  // namespace
}  // namespace pellicle
