// Case files: every rejected input is reported before any computation with
// `file:line:col: key: expected …, found …`, all problems at once; --set overrides apply.
#include <gtest/gtest.h>

#include "pellicle/core/error.hpp"
#include "pellicle/io/problem_size.hpp"
#include "support/case_text.hpp"

namespace pellicle {
namespace {

const std::string kValid = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.1

[solver]
end_time = 0.1
dt = 0.001

[[material]]
name = "steel"
model = "linear-elastic"
density = 7800.0
youngs_modulus = 2e11
poisson_ratio = 0.3

[[body]]
name = "block"
material = "steel"
region = { shape = "box", lower = [0.2, 0.2], upper = [0.6, 0.6] }
)";

using testing::problems_of;

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(CaseReader, ValidCaseIsAccepted) {
  EXPECT_EQ(problems_of(kValid), "");
}

TEST(CaseReader, UnknownKeyNamesFileLineAndKey) {
  const std::string msg =
      problems_of(replace(kValid, "dt = 0.001", "dt = 0.001\nshceme = \"usl\""));
  EXPECT_EQ(msg,
            "case.toml:10:1: solver.shceme: unknown key (misspelt, or not used by this model)");
}

TEST(CaseReader, WrongTypeSaysExpectedAndFound) {
  const std::string msg = problems_of(replace(kValid, "cell = 0.1", "cell = \"fine\""));
  EXPECT_EQ(msg, "case.toml:5:8: grid.cell: expected a number > 0, found the string \"fine\"");
}

TEST(CaseReader, MissingRequiredValue) {
  const std::string msg = problems_of(replace(kValid, "end_time = 0.1\n", ""));
  EXPECT_NE(msg.find("solver.end_time: expected a number > 0, found nothing (required)"),
            std::string::npos)
      << msg;
}

TEST(CaseReader, OutOfRangeValue) {
  const std::string msg =
      problems_of(replace(kValid, "poisson_ratio = 0.3", "poisson_ratio = 0.5"));
  EXPECT_EQ(msg,
            "case.toml:16:17: material[0].poisson_ratio: expected a number in (-1, 0.5), "
            "found the number 0.5");
}

TEST(CaseReader, UnknownChoiceListsTheOptions) {
  const std::string msg =
      problems_of(replace(kValid, "dt = 0.001", "dt = 0.001\nkernel = \"cubic\""));
  EXPECT_EQ(msg,
            "case.toml:10:10: solver.kernel: expected one of \"linear\", \"ugimp\", "
            "\"quadratic-bspline\" or \"cubic-bspline\", found the string \"cubic\"");
}

TEST(CaseReader, UnknownModelAndMaterialReference) {
  std::string text = replace(kValid, "model = \"linear-elastic\"", "model = \"elastic\"");
  text = replace(text, "material = \"steel\"", "material = \"iron\"");
  const std::string msg = problems_of(text);
  EXPECT_NE(msg.find("material[0].model: expected one of \"linear-elastic\""), std::string::npos);
  EXPECT_NE(msg.find("body[0].material: expected the name of a [[material]], found \"iron\""),
            std::string::npos)
      << msg;
  // The rest of the material table is not reported as unknown once its model is unknown.
  EXPECT_EQ(msg.find("youngs_modulus"), std::string::npos) << msg;
}

TEST(CaseReader, AllProblemsAreReportedTogether) {
  std::string text = replace(kValid, "cell = 0.1", "cell = -1");
  text = replace(text, "density = 7800.0", "density = 0");
  const std::string msg = problems_of(text);
  EXPECT_NE(msg.find("grid.cell: expected a number > 0, found the integer -1"), std::string::npos);
  EXPECT_NE(msg.find("material[0].density: expected a number > 0, found the integer 0"),
            std::string::npos)
      << msg;
}

TEST(CaseReader, GridMustHoldWholeCells) {
  const std::string msg = problems_of(replace(kValid, "cell = 0.1", "cell = 0.3"));
  EXPECT_NE(msg.find("grid.cell: expected (upper − lower)/cell to be a whole number"),
            std::string::npos)
      << msg;
}

TEST(CaseReader, DtAndCflAreExclusive) {
  const std::string msg = problems_of(replace(kValid, "dt = 0.001", "dt = 0.001\ncfl = 0.5"));
  EXPECT_NE(msg.find("solver.cfl: give either dt (fixed) or cfl, not both"), std::string::npos);
}

TEST(CaseReader, VectorLengthFollowsDimension) {
  const std::string msg =
      problems_of(replace(kValid, "lower = [0.2, 0.2]", "lower = [0.2, 0.2, 0.2]"));
  EXPECT_NE(msg.find("body[0].region.lower: expected an array of 2 numbers"), std::string::npos)
      << msg;
}

TEST(CaseReader, UnknownRegionShape) {
  const std::string msg = problems_of(replace(kValid, "shape = \"box\"", "shape = \"cube\""));
  EXPECT_NE(msg.find("body[0].region.shape: expected one of \"box\", \"disk\""), std::string::npos);
  EXPECT_EQ(msg.find("region.lower"), std::string::npos) << msg;  // no follow-on noise
}

TEST(CaseReader, BodyOutsideTheGridHoldsNoPoints) {
  const std::string msg = problems_of(replace(kValid, "lower = [0.2, 0.2], upper = [0.6, 0.6]",
                                              "lower = [2.0, 2.0], upper = [3.0, 3.0]"));
  EXPECT_NE(msg.find("body 'block': the region holds no point inside the grid"), std::string::npos)
      << msg;
}

TEST(CaseReader, ProblemSizeIsBoundedFromTheCaseAlone) {
  // The estimate comes before any point is placed: an upper bound (regions over their
  // bounding boxes) that is not far above what the build places.
  for (const char* name : {"fsi_quarter_circle.toml", "two_disks.toml"}) {
    const auto source = case_source_from_text(testing::case_file(name), name);
    Case<2> c = read_case<2>(*source);
    const ProblemSize size = estimate_problem_size(c);
    const auto s = build_simulation<2>(c);
    const double placed = static_cast<double>(s->points().size());
    EXPECT_GE(size.points, placed) << name;
    EXPECT_LE(size.points, 1.5 * placed) << name;  // a disk fills π/4 of its box
    EXPECT_GE(size.nodes, static_cast<double>(s->grid().node_count())) << name;
  }
}

TEST(CaseReader, AxisymmetricAxisMustBeSlip) {
  std::string text = replace(kValid, "cell = 0.1",
                             "cell = 0.1\nkinematics = \"axisymmetric\"\n"
                             "boundary = { x_min = \"fixed\" }");
  EXPECT_NE(problems_of(text).find("grid.boundary.x_min: expected \"slip\": x_min is the symmetry "
                                   "axis r = 0"),
            std::string::npos);
  text = replace(kValid, "lower = [0.0, 0.0]", "lower = [-1.0, 0.0]");
  text = replace(text, "cell = 0.1", "cell = 0.1\nkinematics = \"axisymmetric\"");
  EXPECT_NE(problems_of(text).find("grid.lower: expected radius lower[0] >= 0"), std::string::npos);
}

TEST(CaseReader, FlipFractionOnlyWithBlend) {
  const std::string msg =
      problems_of(replace(kValid, "dt = 0.001", "dt = 0.001\nflip_fraction = 0.9"));
  EXPECT_NE(msg.find("solver.flip_fraction: only used with velocity_update = \"blend\""),
            std::string::npos);
  EXPECT_EQ(problems_of(replace(kValid, "dt = 0.001",
                                "dt = 0.001\nvelocity_update = \"blend\"\nflip_fraction = 0.9")),
            "");
}

TEST(CaseReader, SyntaxErrorHasItsLocation) {
  const std::string msg = problems_of(replace(kValid, "cell = 0.1", "cell = = 0.1"));
  EXPECT_EQ(msg.rfind("case.toml:5:", 0), 0u) << msg;
}

TEST(CaseReader, DimensionComesFromGridLower) {
  const std::string msg = problems_of(replace(kValid, "lower = [0.0, 0.0]", "lower = [0.0]"));
  EXPECT_EQ(msg,
            "case.toml:3:9: grid.lower: expected an array of 2 (2D) or 3 (3D) numbers, found "
            "an array of 1 elements");
}

TEST(CaseReader, SetOverridesAKey) {
  const auto source = case_source_from_text(
      kValid, "case.toml", {"solver.end_time=0.5", "solver.scheme=usl", "body[0].velocity=[1, 2]"});
  Case<2> c = read_case<2>(*source);
  EXPECT_EQ(c.settings.end_time, 0.5);
  EXPECT_EQ(c.settings.scheme, UpdateScheme::usl);
  EXPECT_EQ(c.bodies[0].velocity, Vec2(1, 2));
}

TEST(CaseReader, BadSetIsReportedWithTheSetting) {
  EXPECT_EQ(problems_of(kValid, {"solver.end_time"}),
            "--set solver.end_time: expected key=value, e.g. --set solver.end_time=0.5");
  EXPECT_EQ(problems_of(kValid, {"solver.end_time=-2"}),
            "--set solver.end_time=-2: solver.end_time: expected a number > 0, found the "
            "integer -2");
  EXPECT_EQ(problems_of(kValid, {"body[3].velocity=[0,0]"}),
            "--set body[3].velocity=[0,0]: body[3].velocity: no element 3 in body");
}

TEST(CaseReader, BareTextInASetIsReportedWithTheSetting) {
  // Not TOML, so read as text; its problems still name the --set argument.
  EXPECT_EQ(problems_of(kValid, {"body[0].material=no,such"}),
            "--set body[0].material=no,such: body[0].material: expected the name of a "
            "[[material]], found \"no,such\"");
}

TEST(CaseReader, NamesThatWouldBreakFilesOrColumnsAreRefused) {
  for (const char* bad : {"a,b", "a\\\"b", "../up", "a/b", "..", ""}) {
    const std::string msg =
        problems_of(replace(kValid, "name = \"block\"", "name = \"" + std::string(bad) + "\""));
    EXPECT_NE(msg.find("case.toml:19:8: body[0].name: expected a name"), std::string::npos)
        << bad << ": " << msg;
  }
  EXPECT_NE(problems_of(kValid, {"case.name=\"a\\nb\""})
                .find("case.name: expected a name without line breaks"),
            std::string::npos);
  EXPECT_EQ(problems_of(kValid, {"case.name=\"drop test 2\""}), "");
}

TEST(CaseReader, NumbersTooSmallToComputeWithAreRefused) {
  const std::string msg = problems_of(kValid, {"material[0].density=1e-320"});
  EXPECT_NE(msg.find("material[0].density: expected a number > 0 of normal size"),
            std::string::npos)
      << msg;
  EXPECT_EQ(problems_of(kValid, {"material[0].density=1e-300"}), "");
}

const std::string kString = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.1
[solver]
end_time = 0.1
[[material]]
name = "wire"
model = "membrane"
density = 1.0
youngs_modulus = 1e6
[[body]]
name = "wire"
material = "wire"
membrane = { shape = "polyline", vertices = [[0.1, 0.5], [0.9, 0.5]], points = 9, thickness = 0.01 }
)";

TEST(CaseReader, ValidMembraneIsAccepted) {
  EXPECT_EQ(problems_of(kString), "");
}

TEST(CaseReader, MembraneBodyNeedsAMembraneMaterial) {
  const std::string msg =
      problems_of(replace(kString, "model = \"membrane\"", "model = \"linear-elastic\""));
  EXPECT_NE(
      msg.find(
          "body[0].material: expected a material with model = \"membrane\" for a membrane body"),
      std::string::npos)
      << msg;
  EXPECT_NE(problems_of(kValid, {"material[0].model=membrane"})
                .find("expected a solid material: model \"membrane\" needs a membrane body"),
            std::string::npos);
}

TEST(CaseReader, MembraneKeysAreChecked) {
  std::string msg = problems_of(replace(kString, ", thickness = 0.01", ""));
  EXPECT_NE(msg.find("body[0].membrane.thickness: expected a number > 0, found nothing (required)"),
            std::string::npos)
      << msg;
  msg = problems_of(replace(kString, "points = 9", "points = 9, spacing = 0.05"));
  EXPECT_NE(msg.find("body[0].membrane.spacing: give either points or spacing"), std::string::npos)
      << msg;
  msg = problems_of(replace(kString, "shape = \"polyline\"", "shape = \"line\""));
  EXPECT_NE(msg.find("body[0].membrane.shape: expected one of \"polyline\", \"circle\", "
                     "\"ellipse\" or \"spline\""),
            std::string::npos)
      << msg;
  for (const char* count : {"points = 0", "points = 1"}) {
    msg = problems_of(replace(kString, "points = 9", count));
    EXPECT_NE(msg.find("body[0].membrane.points: expected an integer in [2, "), std::string::npos)
        << count << ": " << msg;
  }
  msg = problems_of(replace(kString, "[[0.1, 0.5], [0.9, 0.5]]", "[[0.1, 0.5], [0.1, 0.5]]"));
  EXPECT_NE(msg.find("body[0].membrane.vertices: expected points that are not all the same"),
            std::string::npos)
      << msg;
  msg = problems_of(replace(kString, "[0.9, 0.5]", "[1.9, 0.5]"));
  EXPECT_NE(msg.find("body 'wire': membrane points lie outside the grid"), std::string::npos)
      << msg;
}

TEST(CaseReader, PointMassesAndInitialStrainRangesMustExist) {
  std::string msg = problems_of(kString, {"body[0].point_masses=[[9, 3.3]]"});
  EXPECT_NE(msg.find("body 'wire': no point 9 (it has 9)"), std::string::npos) << msg;
  EXPECT_EQ(problems_of(kString, {"body[0].point_masses=[[8, 3.3]]"}), "");
  msg = problems_of(kString, {"body[0].initial_strain={xx=0.01, points=[2, 12]}"});
  EXPECT_NE(msg.find("body 'wire': no point 12 (it has 9)"), std::string::npos) << msg;
  msg = problems_of(kString, {"body[0].initial_stress={xx=1.0}"});
  EXPECT_NE(msg.find("body[0].initial_stress: membranes take initial_strain"), std::string::npos)
      << msg;
}

TEST(CaseReader, MeshFileMustBeReadable) {
  const std::string msg = problems_of(R"(
[grid]
lower = [0.0, 0.0, 0.0]
upper = [1.0, 1.0, 1.0]
cell = 0.1
[solver]
end_time = 0.1
[[material]]
name = "skin"
model = "membrane"
density = 1.0
youngs_modulus = 1e6
[[body]]
name = "skin"
material = "skin"
membrane = { shape = "mesh", file = "no_such_file.stl", thickness = 0.01 }
)");
  EXPECT_NE(msg.find("body[0].membrane.file: ./no_such_file.stl: cannot open the STL file"),
            std::string::npos)
      << msg;
}

TEST(CaseReader, ProbesNameRealBodiesAndPoints) {
  std::string msg = problems_of(
      kString + "[[probe]]\nname = \"p\"\nbody = \"rope\"\npoint = 0\nquantity = \"position\"\n");
  EXPECT_NE(msg.find("probe[0].body: expected the name of a [[body]], found \"rope\""),
            std::string::npos)
      << msg;
  msg = problems_of(kString + "[[probe]]\nname = \"p\"\nbody = \"wire\"\nquantity = \"speed\"\n");
  EXPECT_NE(
      msg.find(
          "probe[0].quantity: expected one of \"position\", \"velocity\", \"angle\" or \"radius\""),
      std::string::npos)
      << msg;
}

const std::string kGas = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.1
[solver]
end_time = 0.1
dt = 1e-4
[[material]]
name = "air"
model = "gas"
gamma = 1.4
density = 1.2
[[body]]
name = "air"
material = "air"
internal_energy = 2e5
region = { shape = "box", lower = [0.0, 0.0], upper = [1.0, 1.0] }
)";

TEST(CaseReader, GasCaseIsAccepted) {
  EXPECT_EQ(problems_of(kGas), "");
}

TEST(CaseReader, GasKeysAreChecked) {
  std::string msg = problems_of(kGas, {"material[0].gamma=1.0"});
  EXPECT_NE(msg.find("material[0].gamma: expected a number > 1, found the number 1"),
            std::string::npos)
      << msg;
  msg = problems_of(kGas, {"material[0].artificial_viscosity={linear=-1.0}"});
  EXPECT_NE(msg.find("material[0].artificial_viscosity.linear: expected a number >= 0"),
            std::string::npos)
      << msg;
  msg = problems_of(kGas, {"material[0].density_update=\"cells\""});
  EXPECT_NE(msg.find("material[0].density_update: expected one of \"continuity\" or "
                     "\"cell-quadratic\""),
            std::string::npos)
      << msg;
  msg = problems_of(kGas, {"grid.kinematics=\"plane-stress\""});
  EXPECT_NE(msg.find("material[0].model: a fluid needs grid.kinematics"), std::string::npos) << msg;
  msg = problems_of(kGas, {"body[0].internal_energy=-1.0"});
  EXPECT_NE(msg.find("body[0].internal_energy: expected a number >= 0"), std::string::npos) << msg;
}

TEST(CaseReader, InternalEnergyOnlyForFluids) {
  const std::string msg = problems_of(kValid, {"body[0].internal_energy=1.0"});
  EXPECT_NE(msg.find("body[0].internal_energy: only fluid bodies"), std::string::npos) << msg;
}

TEST(CaseReader, PointVelocitiesNameRealPoints) {
  std::string msg = problems_of(kGas, {"body[0].point_velocities=[[1e6, 0.0, 1.0]]"});
  EXPECT_NE(msg.find("body 'air': no point 1000000 (it has 400)"), std::string::npos) << msg;
  msg = problems_of(kGas, {"body[0].point_velocities=[[0.5, 0.0, 1.0]]"});
  EXPECT_NE(msg.find("body[0].point_velocities: expected [[index, v_x, v_y], …]"),
            std::string::npos)
      << msg;
}

TEST(CaseReader, ContactKeysAreChecked) {
  std::string msg = problems_of(kValid, {"contact={model=\"glue\"}"});
  EXPECT_NE(msg.find("contact.model: expected one of \"single-field\", \"release\" or "
                     "\"friction\""),
            std::string::npos)
      << msg;
  msg = problems_of(kValid, {"contact={model=\"release\", master=\"anvil\"}"});
  EXPECT_NE(msg.find("contact.master: expected the name of a [[body]], found \"anvil\""),
            std::string::npos)
      << msg;
  msg = problems_of(kValid, {"contact={model=\"friction\", coefficient=-0.1}"});
  EXPECT_NE(msg.find("contact.coefficient: expected a number"), std::string::npos) << msg;
  msg = problems_of(kValid, {"contact={model=\"friction\"}"});
  EXPECT_NE(msg.find("contact.coefficient: expected a number"), std::string::npos) << msg;
  msg = problems_of(kValid, {"contact={model=\"release\"}", "solver.scheme=\"usf\""});
  EXPECT_NE(msg.find("contact.model: contact models work with solver.scheme"), std::string::npos)
      << msg;
  msg = problems_of(kValid, {"contact={model=\"single-field\", criterion=\"both\"}"});
  EXPECT_NE(msg.find("contact.criterion: unknown key"), std::string::npos) << msg;
  EXPECT_EQ(problems_of(kValid, {"contact={model=\"friction\", coefficient=inf}"}), "");
  EXPECT_EQ(problems_of(kValid, {"contact={model=\"release\", hysteresis=false}"}), "");
  msg = problems_of(kValid, {"contact={model=\"friction\", coefficient=0.3, hysteresis=true}"});
  EXPECT_NE(msg.find("contact.hysteresis: unknown key"), std::string::npos) << msg;
}

}  // namespace
}  // namespace pellicle
