// Point stresses projected onto the grid nodes (mpm/grid_projection.hpp): uniform states
// project to themselves, pressure is taken from fluid points only and membrane stress from
// membrane points only, and the weights are the run's kernel (a quadratic field picks up
// the kernel's second moment, which differs between kernels).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "pellicle/mpm/grid_projection.hpp"
#include "support/case_text.hpp"

namespace pellicle {
namespace {

using testing::simulation_from_text;

//! Whether a point of body `body` lies within `radius` cells of node `node` on every axis
//! (the kernel's support: the weight is positive strictly inside it).
template <int D>
bool reached_by(const Simulation<D>& s, int body, long node, double radius) {
  const auto& p = s.points();
  const Vec<D> x = s.grid().node_position(node);
  for (long i = p.bodies[body].begin; i < p.bodies[body].end; ++i)
    if (((p.position[i] - x).array().abs() < radius * s.grid().cell()).all()) return true;
  return false;
}

template <int D>
void expect_sym_near(const Sym<D>& actual, const Sym<D>& expected, double tolerance,
                     const std::string& where) {
  for (int k = 0; k < kSymComponents<D>; ++k)
    EXPECT_NEAR(actual[k], expected[k], tolerance) << where << ", component " << k;
}

// Gas (p = (γ − 1) ρ e = 100) in the left half, a solid with a uniform initial stress in the
// right half; quadratic B-splines reach 1.5 cells.
const std::string kGasAndSolid = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.1
boundary = { x_min = "slip", x_max = "slip", y_min = "slip", y_max = "slip" }
[solver]
end_time = 0.01
dt = 1e-4
kernel = "quadratic-bspline"
[[material]]
name = "gas"
model = "gas"
gamma = 1.4
density = 1.0
[[material]]
name = "steel"
model = "linear-elastic"
density = 10.0
youngs_modulus = 1.0e6
[[body]]
name = "gas"
material = "gas"
internal_energy = 250.0
region = { shape = "box", lower = [0.0, 0.0], upper = [0.5, 1.0] }
[[body]]
name = "block"
material = "steel"
region = { shape = "box", lower = [0.5, 0.0], upper = [1.0, 1.0] }
initial_stress = { xx = 300.0, yy = -200.0, zz = 50.0, xy = 75.0 }
)";

TEST(GridProjection, UniformGasPressureAndSolidStressProjectExactly) {
  const auto s = simulation_from_text<2>(kGasAndSolid);
  const auto& p = s->points();
  const double pressure = 100.0;
  Sym<2> gas_stress, block_stress;
  gas_stress << -pressure, -pressure, -pressure, 0.0;
  block_stress << 300.0, -200.0, 50.0, 75.0;
  // The states the projection starts from: the gas settled to −p I, the block as given.
  for (long i = 0; i < p.size(); ++i)
    ASSERT_NEAR((p.stress[i] - (p.body[i] == 0 ? gas_stress : block_stress)).norm(), 0.0,
                1e-12 * pressure)
        << "point " << i;

  GridProjection<2> projection;
  const NodeStresses<2>& f = projection.project(*s);
  const long nodes = s->grid().node_count();
  ASSERT_EQ(static_cast<long>(f.pressure.size()), nodes);
  ASSERT_EQ(static_cast<long>(f.stress.size()), nodes);
  ASSERT_EQ(static_cast<long>(f.membrane_stress.size()), nodes);
  int gas_only = 0, block_only = 0, both = 0;
  for (long n = 0; n < nodes; ++n) {
    const bool gas = reached_by(*s, 0, n, 1.5), block = reached_by(*s, 1, n, 1.5);
    const std::string where = "node " + std::to_string(n);
    EXPECT_EQ(f.membrane_stress[n], Sym<2>::Zero()) << where;  // no membrane in this run
    if (gas) {
      // Fluid points only: the block's stress does not leak into the pressure.
      EXPECT_NEAR(f.pressure[n], pressure, 1e-12 * pressure) << where;
    } else {
      EXPECT_EQ(f.pressure[n], 0.0) << where;
    }
    if (gas && !block) {
      ++gas_only;
      expect_sym_near<2>(f.stress[n], gas_stress, 1e-12 * pressure, where);
    } else if (block && !gas) {
      ++block_only;
      expect_sym_near<2>(f.stress[n], block_stress, 1e-12 * 300.0, where);
    } else if (gas && block) {
      ++both;  // a mass-weighted mix of the two, strictly between them
      EXPECT_GT(f.stress[n][0], -pressure) << where;
      EXPECT_LT(f.stress[n][0], 300.0) << where;
    } else {
      EXPECT_EQ(f.stress[n], Sym<2>::Zero()) << where;
    }
  }
  // Gas reaches the node columns x = −0.1 … 0.6, the block x = 0.4 … 1.1, both the rows
  // y = −0.1 … 1.1: 5 columns of gas-only nodes, 3 mixed, 5 block-only, 13 rows each.
  EXPECT_EQ(gas_only, 5 * 13);
  EXPECT_EQ(block_only, 5 * 13);
  EXPECT_EQ(both, 3 * 13);
}

// Gas filling the grid; the test sets the point stresses itself.
std::string gas_filling_grid(const std::string& kernel) {
  return R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.1
[solver]
end_time = 0.01
dt = 1e-4
kernel = ")" +
         kernel + R"("
[[material]]
name = "gas"
model = "gas"
gamma = 1.4
density = 1.0
[[body]]
name = "gas"
material = "gas"
internal_energy = 250.0
region = { shape = "box", lower = [0.0, 0.0], upper = [1.0, 1.0] }
)";
}

TEST(GridProjection, WeightsAreTheRunsKernel) {
  // Pressure q(x) = a + b (x − x0)² on 2 points per cell per direction. At a node reached
  // by a full, symmetric stencil the mass-weighted mean is a + b ((x_i − x0)² + M h²), M the
  // kernel's second moment over the point offsets ±h/4, ±3h/4, ±5h/4:
  //   linear tent          weights 3/4, 1/4          M = 3/16
  //   quadratic B-spline   weights 11/16, 9/32, 1/32  M = 1/4
  const double a = 100.0, b = 1.0e4, x0 = 0.37, h = 0.1, shear = 25.0;
  for (const auto& [kernel, moment, reach] :
       {std::tuple{"linear", 3.0 / 16.0, 1.0}, std::tuple{"quadratic-bspline", 0.25, 1.5}}) {
    SCOPED_TRACE(kernel);
    auto s = simulation_from_text<2>(gas_filling_grid(kernel));
    auto& p = s->points();
    for (long i = 0; i < p.size(); ++i) {
      const double q = a + b * std::pow(p.position[i].x() - x0, 2);
      p.stress[i] << -q, -q, -q, shear;
    }
    GridProjection<2> projection;
    const NodeStresses<2>& f = projection.project(*s);
    int checked = 0;
    for (long n = 0; n < s->grid().node_count(); ++n) {
      const Vec2 x = s->grid().node_position(n);
      // Nodes whose stencil lies inside the filled domain.
      if ((x.array() < reach * h - 1e-9).any() || (x.array() > 1.0 - reach * h + 1e-9).any())
        continue;
      ++checked;
      const double expected = a + b * (std::pow(x.x() - x0, 2) + moment * h * h);
      EXPECT_NEAR(f.pressure[n], expected, 1e-12 * expected) << "node at " << x.transpose();
      EXPECT_NEAR(f.stress[n][0], -expected, 1e-12 * expected);
      EXPECT_NEAR(f.stress[n][3], shear, 1e-12 * expected);
    }
    EXPECT_EQ(checked, reach == 1.0 ? 81 : 49);
  }
}

TEST(GridProjection, MembraneStressComesFromMembranePointsOnly) {
  // A taut horizontal string (uniaxial, σ_xx = E ε = 100) across gas at p = 100.
  const std::string text = gas_filling_grid("quadratic-bspline") + R"(
[[material]]
name = "string"
model = "membrane"
law = "uniaxial"
density = 1.0
youngs_modulus = 1.0e4
[[body]]
name = "string"
material = "string"
membrane = { shape = "polyline", vertices = [[0.2, 0.52], [0.8, 0.52]], spacing = 0.02, thickness = 0.01 }
initial_strain = { xx = 0.01 }
)";
  const auto s = simulation_from_text<2>(text);
  Sym<2> tension;
  tension << 100.0, 0.0, 0.0, 0.0;
  const auto& p = s->points();
  for (long i = p.bodies[1].begin; i < p.bodies[1].end; ++i)
    ASSERT_NEAR((p.stress[i] - tension).norm(), 0.0, 1e-9) << "string point " << i;

  GridProjection<2> projection;
  const NodeStresses<2>& f = projection.project(*s);
  int on_string = 0;
  for (long n = 0; n < s->grid().node_count(); ++n) {
    const std::string where = "node " + std::to_string(n);
    if (reached_by(*s, 1, n, 1.5)) {
      ++on_string;
      expect_sym_near<2>(f.membrane_stress[n], tension, 1e-9, where);
      // The gas around it alone gives the pressure, though the string's points reach here.
      EXPECT_NEAR(f.pressure[n], 100.0, 1e-12 * 100.0) << where;
      // All points' stress mixes the gas's −100 with the string's +100: strictly between.
      EXPECT_GT(f.stress[n][0], -100.0) << where;
      EXPECT_LT(f.stress[n][0], 100.0) << where;
    } else {
      EXPECT_EQ(f.membrane_stress[n], Sym<2>::Zero()) << where;
    }
  }
  EXPECT_EQ(on_string, 9 * 3);  // nodes x = 0.1 … 0.9 on rows y = 0.4, 0.5, 0.6
}

TEST(GridProjection, UniformSolidStressIn3D) {
  const std::string text = R"(
[grid]
lower = [0.0, 0.0, 0.0]
upper = [1.0, 1.0, 1.0]
cell = 0.25
[solver]
end_time = 0.01
dt = 1e-4
kernel = "cubic-bspline"
[[material]]
name = "steel"
model = "linear-elastic"
density = 10.0
youngs_modulus = 1.0e6
[[body]]
name = "block"
material = "steel"
region = { shape = "box", lower = [0.0, 0.0, 0.0], upper = [1.0, 1.0, 1.0] }
initial_stress = { xx = 300.0, yy = -200.0, zz = 50.0, yz = 10.0, xz = -20.0, xy = 75.0 }
)";
  const auto s = simulation_from_text<3>(text);
  Sym<3> stress;
  stress << 300.0, -200.0, 50.0, 10.0, -20.0, 75.0;  // stored order xx yy zz yz xz xy
  GridProjection<3> projection;
  const NodeStresses<3>& f = projection.project(*s);
  int reached = 0;
  for (long n = 0; n < s->grid().node_count(); ++n) {
    const std::string where = "node " + std::to_string(n);
    EXPECT_EQ(f.pressure[n], 0.0) << where;  // no fluid
    if (reached_by(*s, 0, n, 2.0)) {
      ++reached;
      expect_sym_near<3>(f.stress[n], stress, 1e-12 * 300.0, where);
    } else {
      EXPECT_EQ(f.stress[n], Sym<3>::Zero()) << where;
    }
  }
  EXPECT_EQ(reached, 7 * 7 * 7);  // the 5 domain nodes per axis and one ghost each side
}

}  // namespace
}  // namespace pellicle
