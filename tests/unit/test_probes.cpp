// Probes (io/probes.hpp): each kind reads its points' current state, with values worked by
// hand on a few placed points:
//   position, velocity  the point's own vector, one column per axis (<name>.x, .y[, .z])
//   angle               of the line from points[0] to points[1] against the reference; in 2D
//                       signed, counter-clockwise positive: atan2(r × d, r · d); in 3D the
//                       unsigned acos(r · d / |r||d|)
//   radius              |x − c|
// Indices are within the probe's body (its points follow other bodies' in the arrays), and
// a body or point that does not exist is an InputError naming it. The probes' columns and
// values follow the others in history.csv.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "pellicle/core/error.hpp"
#include "pellicle/io/output.hpp"
#include "pellicle/io/probes.hpp"
#include "pellicle/mpm/materials/linear_elastic.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {
namespace {

namespace fs = std::filesystem;

//! A simulation of bodies given as lists of (position, velocity) points, elastic, at rest
//! unless given a velocity, on the unit square (cube) of cells 0.25.
template <int D>
std::unique_ptr<Simulation<D>> simulation_of(
    const std::vector<std::pair<std::string, std::vector<std::pair<Vec<D>, Vec<D>>>>>& bodies) {
  FaceConditions<D> faces;
  faces.fill(FaceCondition::free);
  Particles<D> points;
  for (const auto& [name, list] : bodies) {
    points.bodies.push_back({name, 0, Vec<D>::Zero(), points.size(), points.size(), nullptr});
    for (const auto& [x, v] : list) points.add(x, v, 1.0, 1000.0);
  }
  const Kinematics kinematics = D == 2 ? Kinematics::plane_strain : Kinematics::solid;
  std::vector<std::unique_ptr<Material<D>>> materials;
  materials.push_back(std::make_unique<LinearElastic<D>>(kinematics, 1000.0, 1.0e6, 0.3));
  TransferOptions options;
  options.kinematics = kinematics;
  std::unique_ptr<Transfer<D>> transfer;
  for (const auto& kernel : kernel_choices<D>())
    if (kernel.name == "linear") transfer = kernel.make(options, 1.0);
  return std::make_unique<Simulation<D>>(
      SimulationSettings{}, Grid<D>(Vec<D>::Zero(), Vec<D>::Ones(), 0.25, faces), std::move(points),
      std::move(materials), std::move(transfer), Vec<D>::Zero());
}

template <int D>
ProbeSpec<D> spec(const std::string& name, const std::string& body, ProbeQuantity quantity, long a,
                  long b = 0, const Vec<D>& reference = Vec<D>::Zero()) {
  ProbeSpec<D> s;
  s.name = name;
  s.body = body;
  s.quantity = quantity;
  s.a = a;
  s.b = b;
  s.reference = reference;
  s.where = {"case.toml", 7, 1};
  return s;
}

//! A pendulum of three points and a ball of two, in 2D. The pendulum's lines from point 0 at
//! (0.5, 0.8) go to (0.7, 0.6), direction (1, −1), and to (0.3, 0.6), direction (−1, −1);
//! the ball's points are 3-4-5 triangles away from the origin and from each other.
std::unique_ptr<Simulation<2>> pendulum_and_ball() {
  return simulation_of<2>({
      {"pendulum",
       {{Vec2(0.5, 0.8), Vec2::Zero()},
        {Vec2(0.7, 0.6), Vec2(0.25, -1.5)},
        {Vec2(0.3, 0.6), Vec2::Zero()}}},
      {"ball", {{Vec2(0.3, 0.4), Vec2(-2.0, 0.5)}, {Vec2(0.6, 0.8), Vec2::Zero()}}},
  });
}

TEST(Probes, PositionAndVelocityAreThePointsOwnWithOneColumnPerAxis) {
  const auto s = pendulum_and_ball();
  const Probe<2> tip(spec<2>("tip", "pendulum", ProbeQuantity::position, 1), *s);
  EXPECT_EQ(tip.columns(), (std::vector<std::string>{"tip.x", "tip.y"}));
  EXPECT_EQ(tip.values(*s), (std::vector<double>{0.7, 0.6}));
  const Probe<2> speed(spec<2>("speed", "pendulum", ProbeQuantity::velocity, 1), *s);
  EXPECT_EQ(speed.columns(), (std::vector<std::string>{"speed.x", "speed.y"}));
  EXPECT_EQ(speed.values(*s), (std::vector<double>{0.25, -1.5}));
  // Point 0 of the second body is the fourth point of the arrays.
  const Probe<2> ball(spec<2>("ball", "ball", ProbeQuantity::velocity, 0), *s);
  EXPECT_EQ(ball.values(*s), (std::vector<double>{-2.0, 0.5}));
  // A probe reads the state at the time it is asked.
  s->points().position[1] = Vec2(0.125, 0.375);
  EXPECT_EQ(tip.values(*s), (std::vector<double>{0.125, 0.375}));
}

TEST(Probes, AngleIn2DIsSignedCounterClockwiseFromTheReference) {
  const auto s = pendulum_and_ball();
  const Vec2 down(0.0, -1.0), right(1.0, 0.0);
  struct Case {
    long b;
    Vec2 reference;
    double degrees;  // direction of point b seen from point 0, against the reference
  };
  const Case cases[] = {
      {1, down, 45.0},    // (1, −1) is "down" turned 45° counter-clockwise
      {2, down, -45.0},   // (−1, −1): 45° clockwise
      {1, right, -45.0},  // (1, −1) is "right" turned 45° clockwise
      {2, right, -135.0}, {1, 3.0 * down, 45.0},  // the reference's length does not matter
  };
  for (const Case& c : cases) {
    const Probe<2> angle(spec<2>("swing", "pendulum", ProbeQuantity::angle, 0, c.b, c.reference),
                         *s);
    EXPECT_EQ(angle.columns(), std::vector<std::string>{"swing"});
    ASSERT_EQ(angle.values(*s).size(), 1u);
    EXPECT_NEAR(angle.values(*s)[0], c.degrees, 1e-12) << "point " << c.b;
  }
  // Straight up against "down": half a turn.
  s->points().position[1] = Vec2(0.5, 0.9);
  const Probe<2> up(spec<2>("swing", "pendulum", ProbeQuantity::angle, 0, 1, down), *s);
  EXPECT_NEAR(std::abs(up.values(*s)[0]), 180.0, 1e-12);
}

TEST(Probes, RadiusIsTheDistanceFromTheCentre) {
  const auto s = pendulum_and_ball();
  // (0.3, 0.4) from the origin and (0.6, 0.8) from (0.3, 0.4): both 0.5 (3-4-5).
  const Probe<2> from_origin(spec<2>("r", "ball", ProbeQuantity::radius, 0), *s);
  EXPECT_EQ(from_origin.columns(), std::vector<std::string>{"r"});
  EXPECT_NEAR(from_origin.values(*s)[0], 0.5, 1e-15);
  const Probe<2> from_point(spec<2>("r", "ball", ProbeQuantity::radius, 1, 1, Vec2(0.3, 0.4)), *s);
  EXPECT_NEAR(from_point.values(*s)[0], 0.5, 1e-15);
}

TEST(Probes, In3DAnglesAreUnsignedAndVectorsHaveThreeColumns) {
  const auto s = simulation_of<3>({{"rod",
                                    {{Vec3(0.5, 0.5, 0.8), Vec3::Zero()},
                                     {Vec3(0.5, 0.7, 0.6), Vec3(1.0, 2.0, 3.0)},
                                     {Vec3(0.5, 0.3, 0.6), Vec3::Zero()},
                                     {Vec3(0.5, 0.5, 0.9), Vec3::Zero()}}}});
  const Vec3 down(0.0, 0.0, -1.0);
  const Probe<3> v(spec<3>("v", "rod", ProbeQuantity::velocity, 1), *s);
  EXPECT_EQ(v.columns(), (std::vector<std::string>{"v.x", "v.y", "v.z"}));
  EXPECT_EQ(v.values(*s), (std::vector<double>{1.0, 2.0, 3.0}));
  // (0, 1, −1) and (0, −1, −1) are both 45° from "down"; (0, 0, 1) is 180° from it.
  for (long b : {1L, 2L}) {
    const Probe<3> a(spec<3>("a", "rod", ProbeQuantity::angle, 0, b, down), *s);
    EXPECT_NEAR(a.values(*s)[0], 45.0, 1e-12) << "point " << b;
  }
  const Probe<3> up(spec<3>("a", "rod", ProbeQuantity::angle, 0, 3, down), *s);
  EXPECT_NEAR(up.values(*s)[0], 180.0, 1e-12);
  // |(0.5, 0.5, 0.9) − (0.5, 0.2, 0.5)| = |(0, 0.3, 0.4)| = 0.5.
  const Probe<3> r(spec<3>("r", "rod", ProbeQuantity::radius, 3, 3, Vec3(0.5, 0.2, 0.5)), *s);
  EXPECT_NEAR(r.values(*s)[0], 0.5, 1e-15);
}

//! The message of the InputError that binding `spec` raises, "" when it binds.
std::string refusal(const ProbeSpec<2>& spec, const Simulation<2>& s) {
  try {
    Probe<2> probe(spec, s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Probes, ABodyOrPointThatDoesNotExistIsRefusedByName) {
  const auto s = pendulum_and_ball();
  EXPECT_EQ(refusal(spec<2>("tip", "pendulum", ProbeQuantity::position, 2), *s), "");
  EXPECT_EQ(refusal(spec<2>("tip", "rope", ProbeQuantity::position, 0), *s),
            "case.toml:7:1: probe.body: no body named \"rope\"");
  EXPECT_EQ(refusal(spec<2>("tip", "pendulum", ProbeQuantity::position, 3), *s),
            "case.toml:7:1: probe.point: probe 'tip': body 'pendulum' has no point 3 (it has 3)");
  // The ball has two points: the angle's second point is checked as well.
  EXPECT_EQ(refusal(spec<2>("tilt", "ball", ProbeQuantity::angle, 0, 2, Vec2(0, -1)), *s),
            "case.toml:7:1: probe.point: probe 'tilt': body 'ball' has no point 2 (it has 2)");
  // A negative index is no point of the body either (it would read the body before it).
  EXPECT_EQ(refusal(spec<2>("tip", "ball", ProbeQuantity::position, -1), *s),
            "case.toml:7:1: probe.point: probe 'tip': body 'ball' has no point -1 (it has 2)");
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Probes, HistoryCarriesTheProbeColumnsAfterTheOthers) {
  const auto s = pendulum_and_ball();
  std::vector<Probe<2>> probes;
  probes.emplace_back(spec<2>("tip", "pendulum", ProbeQuantity::position, 1), *s);
  probes.emplace_back(spec<2>("r", "ball", ProbeQuantity::radius, 0), *s);
  const fs::path dir = fs::temp_directory_path() / "pellicle_test_probes";
  fs::remove_all(dir);
  OutputSettings settings;
  settings.directory = dir.string();
  { OutputWriter<2> output(settings, *s, std::move(probes)); }  // header and the t = 0 row
  std::istringstream history(read_all(dir / "history.csv"));
  std::string header, row;
  std::getline(history, header);
  std::getline(history, row);
  const std::string tail = ",tip.x,tip.y,r";
  ASSERT_GE(header.size(), tail.size());
  EXPECT_EQ(header.substr(header.size() - tail.size()), tail) << header;
  // The row has as many fields as the header; its last three are 0.7, 0.6 and 0.5.
  auto fields = [](const std::string& line) {
    std::vector<std::string> out;
    std::stringstream in(line);
    for (std::string f; std::getline(in, f, ',');) out.push_back(f);
    return out;
  };
  const auto names = fields(header), values = fields(row);
  ASSERT_EQ(values.size(), names.size()) << row;
  const std::size_t n = values.size();
  EXPECT_DOUBLE_EQ(std::stod(values[n - 3]), 0.7);
  EXPECT_DOUBLE_EQ(std::stod(values[n - 2]), 0.6);
  EXPECT_DOUBLE_EQ(std::stod(values[n - 1]), 0.5);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace pellicle
