// Surface case files: every case under cases/ is accepted (and its cloud built), and each
// rejected input names file, line, key and the problem, formulas with their column.
#include <gtest/gtest.h>

#include "pellicle/core/error.hpp"
#include "pellicle/io/builtin_cases.hpp"
#include "pellicle/io/case.hpp"
#include "pellicle/io/surface_case.hpp"

namespace pellicle {
namespace {

const std::string kValid = R"([surface]
shape = { kind = "sphere", center = [0.0, 0.0, 0.0], radius = 1.0 }
smoothing_length = 0.4
velocity = ["0.5*nx", "0.5*ny", "0.5*nz"]

[pde]
model = "advection-diffusion"
diffusion = 1.0
initial = "x*y"

[solver]
dt = 0.01
end_time = 0.1
)";

//! The InputError text of reading (and building) a surface case ("" when accepted).
std::string problems_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    const auto source = case_source_from_text(text, "surface.toml", sets);
    EXPECT_TRUE(is_surface_case(*source));
    if (surface_case_dimension(*source) == 2) {
      SurfaceCase<2> c = read_surface_case<2>(*source);
      build_surface_simulation<2>(c);
    } else {
      SurfaceCase<3> c = read_surface_case<3>(*source);
      build_surface_simulation<3>(c);
    }
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SurfaceCaseReader, EveryShippedCaseIsAccepted) {
  int surface = 0, mpm = 0;
  for (const auto& [name, text] : builtin_cases()) {
    const auto source = case_source_from_text(text, name);
    if (!is_surface_case(*source)) {
      ++mpm;
      if (case_dimension(*source) == 2)
        read_case<2>(*source);
      else
        read_case<3>(*source);
      continue;
    }
    ++surface;
    EXPECT_EQ(problems_of(text, {"surface.smoothing_length=0.4"}), "") << name;
  }
  EXPECT_GE(surface, 5);
  EXPECT_GE(mpm, 15);
}

TEST(SurfaceCaseReader, ValidCaseAndCurves) {
  EXPECT_EQ(problems_of(kValid), "");
  EXPECT_EQ(problems_of(kValid, {"surface.shape={kind=\"circle\",center=[0.0,0.0],radius=1.0}",
                                 "surface.velocity=[\"nx\",\"ny\"]"}),
            "");
}

void expect_problem(const std::vector<std::string>& sets, const std::string& words) {
  const std::string what = problems_of(kValid, sets);
  EXPECT_NE(what.find(words), std::string::npos) << "expected \"" << words << "\" in: " << what;
}

TEST(SurfaceCaseReader, RejectedInputsNameTheKey) {
  expect_problem({"surface.smoothing_length=-1"}, "surface.smoothing_length");
  expect_problem({"surface.velocity=[\"nx\",\"ny\"]"},
                 "surface.velocity: expected an array of 3 formulas");
  expect_problem({"surface.velocity=[\"nx\",\"ny\",\"q\"]"},
                 "component 3, column 1 of the formula: unknown name 'q'");
  expect_problem({"pde.initial=\"x*\""}, "pde.initial: column 3 of the formula");
  expect_problem({"pde.model=\"heat\""}, "pde.model");
  expect_problem({"pde.diffusion=-1"}, "pde.diffusion");
  expect_problem({"solver.dt=1.0"}, "solver.dt: expected a time step no longer than end_time");
  expect_problem({"surface.management={r_min=0.5, r_max=0.4}"}, "expected r_min below r_max");
  expect_problem({"surface.movement=\"third-order\""}, "surface.movement");
  expect_problem({"surface.spacing_factor=0.05"}, "surface.spacing_factor");
  expect_problem({"solver.preconditioner=\"amg\""}, "solver.preconditioner");
  expect_problem({"pde.boundary=\"dirichlet\""}, "boundary_value");
  expect_problem({"surface.shape={kind=\"cube\"}"}, "surface.shape.kind");
  expect_problem({"surface.colour=1"}, "surface.colour");  // unknown key
}

TEST(SurfaceCaseReader, FileAndLineOfTheKey) {
  // A value given by --set is named by the setting.
  const std::string what = problems_of(kValid, {"pde.initial=\"x +\""});
  EXPECT_NE(what.find("--set pde.initial"), std::string::npos) << what;
  const std::string line = problems_of(
      "[surface]\nshape = { kind = \"sphere\", center = [0.0, 0.0, 0.0], radius = 1.0 }\n"
      "smoothing_length = 0.4\nvelocity = [\"0\", \"0\", \"sin(\"]\n[solver]\ndt = 0.1\n"
      "end_time = 1.0\n");
  EXPECT_NE(line.find("surface.toml:4:"), std::string::npos) << line;
}

}  // namespace
}  // namespace pellicle
