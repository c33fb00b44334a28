// Building in part (SimulationBuilder::select_points, what each rank of a distributed run
// does): every kept point must be built exactly as the whole build builds it, with the
// quantities that belong to a whole body (its mass and centre, a total_mass's density, point
// indices of overrides and initial strains, a rigid body's velocity) taken from the whole body.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pellicle/io/build.hpp"
#include "pellicle/io/case.hpp"

namespace pellicle {
namespace {

const std::string kCase = R"(
[case]
name = "partial"
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.05
[solver]
end_time = 0.1
[[material]]
name = "steel"
model = "linear-elastic"
density = 1000.0
youngs_modulus = 1e6
poisson_ratio = 0.3
[[material]]
name = "plate"
model = "rigid"
density = 1000.0
[[body]]
name = "block"
material = "steel"
points_per_cell = 2
velocity = [0.1, -0.2]
angular_velocity = 3.0
velocity_gradient = [[0.5, 0.1], [0.0, -0.2]]
total_mass = 2.5
point_masses = [[3, 0.5], [40, 0.25], [3, 0.75]]
point_velocities = [[0, 1.0, 2.0], [7, -1.0, 0.5]]
initial_strain = { xx = 0.01, points = [5, 30] }
region = { shape = "box", lower = [0.2, 0.3], upper = [0.6, 0.7] }
[[body]]
name = "plate"
material = "plate"
velocity = [0.0, 0.3]
angular_velocity = 1.0
region = { shape = "box", lower = [0.1, 0.05], upper = [0.9, 0.15] }
)";

std::unique_ptr<Simulation<2>> build(PointSelection<2> select = {}) {
  const auto source = case_source_from_text(kCase, "partial.toml");
  Case<2> c = read_case<2>(*source);
  return build_simulation<2>(c, std::move(select));
}

//! Keeps the points of each body whose index modulo 3 is `rest` (point 0 of each body only
//! when rest is 0).
PointSelection<2> every_third(int rest) {
  return [rest](const Grid<2>&, const std::vector<PlacedBody<2>>& bodies) {
    std::vector<std::vector<char>> keep(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b)
      for (long k = 0; k < bodies[b].count; ++k) keep[b].push_back(static_cast<int>(k % 3) == rest);
    return keep;
  };
}

TEST(PartialBuild, KeptPointsAreBuiltAsInTheWholeBuild) {
  const auto whole = build();
  const auto& w = whole->points();
  for (int rest : {0, 1, 2}) {
    const auto part = build(every_third(rest));
    const auto& p = part->points();
    const auto& index = p.named<double>(column_names::body_index);
    const auto& strain = p.named<Sym<2>>(column_names::strain);
    const auto& whole_strain = w.named<Sym<2>>(column_names::strain);
    ASSERT_EQ(p.bodies.size(), w.bodies.size());
    for (std::size_t b = 0; b < p.bodies.size(); ++b) {
      const auto& body = p.bodies[b];
      EXPECT_EQ(body.built, w.bodies[b].count());
      EXPECT_EQ(body.count(), (w.bodies[b].count() + 2 - rest) / 3) << "rest " << rest;
      EXPECT_EQ(body.applied_acceleration, w.bodies[b].applied_acceleration);
      EXPECT_EQ(body.start_velocity, w.velocity[w.bodies[b].begin]) << body.name;
      for (long i = body.begin; i < body.end; ++i) {
        const long k = static_cast<long>(index[i]);
        ASSERT_EQ(k % 3, rest);
        const long j = w.bodies[b].begin + k;  // the same point of the whole build
        EXPECT_EQ(p.position[i], w.position[j]);
        EXPECT_EQ(p.velocity[i], w.velocity[j]) << body.name << " point " << k;
        EXPECT_EQ(p.mass[i], w.mass[j]) << body.name << " point " << k;
        EXPECT_EQ(p.volume[i], w.volume[j]);
        EXPECT_EQ(p.density[i], w.density[j]);
        EXPECT_EQ(p.stress[i], w.stress[j]) << body.name << " point " << k;
        EXPECT_EQ(strain[i], whole_strain[j]);
      }
    }
  }
}

TEST(PartialBuild, NoPointKeptLeavesTheBodyEmptyButKnown) {
  const auto part = build([](const Grid<2>&, const std::vector<PlacedBody<2>>& bodies) {
    std::vector<std::vector<char>> keep(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) keep[b].assign(bodies[b].count, 0);
    return keep;
  });
  EXPECT_EQ(part->point_count(), 0);
  const auto whole = build();
  for (std::size_t b = 0; b < whole->points().bodies.size(); ++b)
    EXPECT_EQ(part->points().bodies[b].built, whole->points().bodies[b].count());
}

}  // namespace
}  // namespace pellicle
