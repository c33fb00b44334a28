#include "pellicle/io/bench_case.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "pellicle/io/build.hpp"
#include "pellicle/io/builtin_cases.hpp"
#include "pellicle/io/case.hpp"

namespace pellicle {

std::unique_ptr<Simulation<2>> make_bench_two_disks(long points, const std::string& kernel,
                                                    const std::string& velocity_update,
                                                    const std::vector<std::string>& extra) {
  // Two disks of radius 0.2 cover 2π 0.2² of the unit square; 4 points per covered cell.
  const double area = 2.0 * std::numbers::pi * 0.04;
  const long cells = std::max(4L, std::lround(std::sqrt(points / (4.0 * area))));
  char cell[64];
  std::snprintf(cell, sizeof cell, "grid.cell=%.17g", 1.0 / cells);
  std::vector<std::string> overrides{cell,
                                     "solver.kernel=" + kernel,
                                     "solver.scheme=musl",
                                     "solver.velocity_update=" + velocity_update,
                                     "solver.end_time=1000",
                                     "body[0].points_per_cell=2",
                                     "body[1].points_per_cell=2"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  const auto source =
      case_source_from_text(builtin_case("two_disks.toml"), "two_disks.toml", overrides);
  Case<2> c = read_case<2>(*source);
  return build_simulation<2>(c);
}

std::unique_ptr<Simulation<2>> make_bench_gas_box(long points, const std::string& kernel,
                                                  const std::string& velocity_update) {
  // A closed unit box of gas with shock viscosity, 4 points per cell, a small velocity
  // field so the energy equation and the artificial viscosity do real work.
  const long cells = std::max(4L, std::lround(std::sqrt(points / 4.0)));
  char cell[64], dt[64];
  std::snprintf(cell, sizeof cell, "grid.cell=%.17g", 1.0 / cells);
  std::snprintf(dt, sizeof dt, "solver.dt=%.17g", 0.2 / cells / 1000.0);
  const std::string text = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.1
boundary = { x_min = "slip", x_max = "slip", y_min = "slip", y_max = "slip" }
[solver]
end_time = 1000.0
dt = 1e-5
[[material]]
name = "air"
model = "gas"
gamma = 1.4
density = 1.0
viscosity = 1e-3
artificial_viscosity = { linear = 0.2, quadratic = 1.0 }
[[body]]
name = "air"
material = "air"
internal_energy = 2.5e5
points_per_cell = 2
velocity_gradient = [[-1.0, 0.0], [0.0, 0.5]]
region = { shape = "box", lower = [0.0, 0.0], upper = [1.0, 1.0] }
)";
  const auto source = case_source_from_text(
      text, "<gas benchmark>",
      {cell, dt, "solver.kernel=" + kernel, "solver.velocity_update=" + velocity_update});
  Case<2> c = read_case<2>(*source);
  return build_simulation<2>(c);
}

std::unique_ptr<Simulation<2>> make_bench_gas_membrane(long points) {
  // The quarter disk of radius 0.5 holds π/16 of the unit square, 16 gas points per cell:
  // points ≈ π cells².
  const long cells =
      std::max(10L, std::lround(std::sqrt(std::max(points, 100L) / std::numbers::pi)));
  const double h = 1.0 / cells;
  char cell[64], dt[64], spacing[96];
  std::snprintf(cell, sizeof cell, "grid.cell=%.17g", h);
  std::snprintf(dt, sizeof dt, "solver.dt=%.17g", 0.7e-4 * h / 0.1);
  std::snprintf(spacing, sizeof spacing, "body[0].membrane.points=%ld",
                std::lround(std::numbers::pi / 4.0 / (0.25 * h)) + 1);
  const auto source =
      case_source_from_text(builtin_case("fsi_quarter_circle.toml"), "<gas-membrane benchmark>",
                            {cell, dt, spacing, "solver.end_time=1000"});
  Case<2> c = read_case<2>(*source);
  return build_simulation<2>(c);
}

std::unique_ptr<Simulation<3>> make_bench_two_spheres(long points, const std::string& kernel,
                                                      const std::string& velocity_update,
                                                      const std::string& scheme) {
  // Two balls of radius 0.2, 8 points per covered cell: points = 16 (4π/3) 0.2³ cells³.
  const double per_cell_cubed = 16.0 * 4.0 / 3.0 * std::numbers::pi * 0.008;
  const long cells = std::max(8L, std::lround(std::cbrt(points / per_cell_cubed)));
  char cell[64];
  std::snprintf(cell, sizeof cell, "grid.cell=%.17g", 1.0 / cells);
  const std::string text = R"(
[grid]
lower = [0.0, 0.0, 0.0]
upper = [1.0, 1.0, 1.0]
cell = 0.1
kinematics = "solid"
[solver]
end_time = 1000.0
cfl = 0.4
[[material]]
name = "elastic"
model = "linear-elastic"
density = 1000.0
youngs_modulus = 1000.0
poisson_ratio = 0.3
[[body]]
name = "lower-sphere"
material = "elastic"
points_per_cell = 2
velocity = [0.1, 0.1, 0.1]
region = { shape = "sphere", center = [0.25, 0.25, 0.25], radius = 0.2 }
[[body]]
name = "upper-sphere"
material = "elastic"
points_per_cell = 2
velocity = [-0.1, -0.1, -0.1]
region = { shape = "sphere", center = [0.75, 0.75, 0.75], radius = 0.2 }
)";
  const auto source = case_source_from_text(
      text, "<3D benchmark>",
      {cell, "solver.kernel=" + kernel, "solver.velocity_update=" + velocity_update,
       "solver.scheme=" + scheme});
  Case<3> c = read_case<3>(*source);
  return build_simulation<3>(c);
}

}  // namespace pellicle
