#include "pellicle/io/bench_case.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "pellicle/io/build.hpp"
#include "pellicle/io/case.hpp"

namespace pellicle {

std::unique_ptr<Simulation<2>> make_bench_two_disks(long points, const std::string& kernel,
                                                    const std::string& velocity_update) {
  // Two disks of radius 0.2 cover 2π 0.2² of the unit square; 4 points per covered cell.
  const double area = 2.0 * std::numbers::pi * 0.04;
  const long cells = std::max(4L, std::lround(std::sqrt(points / (4.0 * area))));
  char cell[64];
  std::snprintf(cell, sizeof cell, "grid.cell=%.17g", 1.0 / cells);
  const auto source =
      load_case_source("", {cell, "solver.kernel=" + kernel, "solver.scheme=musl",
                            "solver.velocity_update=" + velocity_update, "solver.end_time=1000",
                            "body[0].points_per_cell=2", "body[1].points_per_cell=2"});
  Case<2> c = read_case<2>(*source);
  return build_simulation<2>(c);
}

}  // namespace pellicle
