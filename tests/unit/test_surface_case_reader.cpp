// Surface case files: every case under cases/ is accepted (and its cloud built), and each
// rejected input names file, line, key and the problem, formulas with their column.
#include <gtest/gtest.h>

#include "pellicle/core/error.hpp"
#include "pellicle/io/builtin_cases.hpp"
#include "pellicle/io/case.hpp"
#include "pellicle/io/problem_size.hpp"
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
  // Several surfaces and contact (§3.6).
  const std::string both =
      problems_of(kValid, {"surface.shapes=[{kind=\"sphere\",center=[3,0,0],radius=1.0}]"});
  EXPECT_NE(both.find("surface.shapes: expected either `shape` (one surface) or `shapes`"),
            std::string::npos)
      << both;
  EXPECT_EQ(both.find("unknown key"), std::string::npos) << both;  // one problem, not two
  expect_problem({"surface.contact={between=\"glue\"}"},
                 "surface.contact.between: expected one of");
  expect_problem(
      {"surface.contact={rules=[{surfaces=[\"surface\",\"other\"],response=\"merge\"}]}"},
      "surface.contact.rules[0].surfaces: expected two surface names out of: surface");
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

// The initial cloud's size, estimated from the shape's length or area before sampling, is
// within a few per cent of the cloud sampled (boundary points come on top in open shapes).
TEST(SurfaceCaseReader, CloudSizeIsEstimatedFromTheShape) {
  const auto compare = [](const std::string& text, const std::vector<std::string>& sets,
                          const std::string& name) {
    const auto source = case_source_from_text(text, name, sets);
    const auto check = [&](const auto& c) {
      const double estimate = estimate_surface_size(c.shapes(), c.spacing).points;
      const double sampled = static_cast<double>(c.sample.size());
      EXPECT_NEAR(estimate / sampled, 1.0, 0.08)
          << name << ": " << c.surfaces[0].shape->describe() << ", estimate " << estimate
          << ", sampled " << sampled;
    };
    if (surface_case_dimension(*source) == 2)
      check(read_surface_case<2>(*source));
    else
      check(read_surface_case<3>(*source));
  };
  for (const auto& [name, text] : builtin_cases())
    if (is_surface_case(*case_source_from_text(text, name))) compare(text, {}, name);
  const std::string h = "surface.smoothing_length=0.1";
  for (const std::string shape :
       {"{kind=\"sphere\",center=[0.0,0.0,0.0],radius=1.0,keep=[[0.0,0.6,0.8]]}",
        "{kind=\"ellipsoid\",center=[0.0,0.0,0.0],semi_axes=[1.0,0.5,0.3]}",
        "{kind=\"torus\",center=[0.0,0.0,0.0],major_radius=1.0,minor_radius=0.3}",
        "{kind=\"half-pipe\",side=\"outer\"}",
        "{kind=\"implicit-blobs\",centers=[[0.0,0.0,0.0],[0.8,0.0,0.0]],radii=[0.6,0.5],"
        "level=0.5}"})
    compare(kValid, {"surface.shape=" + shape, h}, "3d.toml");
  const std::string plane = "surface.velocity=[\"0\",\"0\"]";
  for (const std::string shape :
       {"{kind=\"circle\",center=[0.0,0.0],radius=10.0}",
        "{kind=\"circle\",center=[0.0,0.0],radius=10.0,keep=[[0.0,1.0]]}",
        "{kind=\"ellipse\",center=[0.0,0.0],semi_axes=[10.0,2.0]}",
        "{kind=\"implicit-blobs\",centers=[[0.0,0.0],[8.0,0.0]],radii=[6.0,5.0],level=0.5}"})
    compare(kValid, {"surface.shape=" + shape, plane, h}, "2d.toml");
}

// A cloud too large for the machine, or for its indices, is refused before it is sampled,
// at the key that sets its spacing; slender tori and pipes (whose sampling carriers grow
// with the ratio of their radii) are refused too.
TEST(SurfaceCaseReader, OversizedCloudsAreRefusedBeforeSampling) {
  const std::string sphere = R"([surface]
shape = { kind = "sphere", center = [0.0, 0.0, 0.0], radius = 1e6 }
smoothing_length = 1e-3
[solver]
dt = 0.01
end_time = 0.1
)";
  std::string what = problems_of(sphere);
  EXPECT_NE(what.find("surface.toml:3:20: surface.smoothing_length: the initial cloud would hold "
                      "about 7.48e+19 points (area 1.26e+13 at spacing 0.000392), more than the "
                      "2.15e+09 a cloud can index"),
            std::string::npos)
      << what;
  // Spacings so small that the count overflows a double.
  what = problems_of(sphere, {"surface.smoothing_length=1e-300"});
  EXPECT_NE(what.find("--set surface.smoothing_length=1e-300: surface.smoothing_length: the "
                      "initial cloud would hold about inf points"),
            std::string::npos)
      << what;
  // Below the index limit, above any machine's memory: about 8e8 points, 3 TB.
  what = problems_of(kValid, {"surface.smoothing_length=3e-4"});
  EXPECT_NE(what.find("surface.smoothing_length: the problem needs about 3.41e+03 GB (8.31e+08 "
                      "points: area 12.6 at spacing 0.000118), more than the"),
            std::string::npos)
      << what;
  EXPECT_NE(what.find("this machine has available: raise surface.smoothing_length"),
            std::string::npos)
      << what;
  expect_problem({"surface.shape={kind=\"torus\",center=[0.0,0.0,0.0],major_radius=1.0,"
                  "minor_radius=1e-9}"},
                 "surface.shape.minor_radius: expected minor_radius at least major_radius / 1000");
  expect_problem({"surface.shape={kind=\"half-pipe\",pipe_radius=1e-9}"},
                 "surface.shape.pipe_radius: expected pipe_radius at least arc_radius / 1000");
}

}  // namespace
}  // namespace pellicle
