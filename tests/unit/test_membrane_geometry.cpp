// Membrane geometry: curves sampled at equal arc length, surface meshes and their areas,
// STL and OBJ files, and frames from connectivity.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>

#include "pellicle/core/error.hpp"
#include "pellicle/geometry/curve.hpp"
#include "pellicle/geometry/surface_mesh.hpp"
#include "pellicle/normals/connectivity.hpp"

namespace pellicle {
namespace {

constexpr double pi = std::numbers::pi;

TEST(Curves, PolylineEndsAndSpacing) {
  // The seeds' spring: 10 points from (0.05, 1.99) to (0.05, 1.69), each standing for the
  // spacing 0.3/9 (mass ρ A Δs = 3.33e-4 with ρ = A = 0.1, IJNME §3.1.1).
  const SampledCurve c = sample_polyline({Vec2(0.05, 1.99), Vec2(0.05, 1.69)}, false, {0.0, 10});
  ASSERT_EQ(c.points.size(), 10u);
  EXPECT_LT((c.points.front() - Vec2(0.05, 1.99)).norm(), 1e-12);
  EXPECT_LT((c.points.back() - Vec2(0.05, 1.69)).norm(), 1e-12);
  for (double l : c.lengths) EXPECT_NEAR(l, 0.3 / 9, 1e-12);
  // By spacing, around a corner: about 2.0/0.1 gaps, all on the polyline.
  const SampledCurve l = sample_polyline({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1)}, false, {0.1, 0});
  EXPECT_EQ(l.points.size(), 21u);
  for (const auto& x : l.points) EXPECT_LT(std::min(std::abs(x.y()), std::abs(x.x() - 1)), 1e-9);
}

TEST(Curves, CircleIsClosedAndEvenlySpaced) {
  const SampledCurve c = sample_ellipse_arc(Vec2(0.5, 0.5), Vec2(0.3, 0.3), 0.0, 2 * pi, {0.01, 0});
  EXPECT_TRUE(c.closed);
  double total = 0.0;
  for (double l : c.lengths) total += l;
  EXPECT_NEAR(total, 2 * pi * 0.3, 1e-6);
  for (const auto& x : c.points) EXPECT_NEAR((x - Vec2(0.5, 0.5)).norm(), 0.3, 1e-12);
  for (std::size_t i = 0; i < c.points.size(); ++i)  // neighbours equally far apart
    EXPECT_NEAR((c.points[(i + 1) % c.points.size()] - c.points[i]).norm(), c.lengths[i], 1e-5);
}

TEST(Curves, SplinePassesThroughItsPoints) {
  const std::vector<Vec2> through{Vec2(0, 0), Vec2(1, 0.5), Vec2(2, 0), Vec2(3, 0.5)};
  const SampledCurve c = sample_spline(through, false, {0.0, 301});  // 100 per piece
  for (int k = 0; k < 4; ++k) {
    double nearest = 1e9;
    for (const auto& x : c.points) nearest = std::min(nearest, (x - through[k]).norm());
    EXPECT_LT(nearest, 0.02) << "point " << k;
  }
}

TEST(SurfaceMeshes, AreasOfTheGeneratedShapes) {
  auto area = [](const SurfaceMesh& m) {
    double a = 0.0;
    for (double v : vertex_areas(m)) a += v;
    return a;
  };
  EXPECT_NEAR(area(make_ellipsoid(Vec3::Zero(), Vec3::Ones(), 0.05)), 4 * pi, 0.005 * 4 * pi);
  EXPECT_NEAR(area(make_disk(Vec3::Zero(), Vec3::UnitZ(), 1.0, 0.05)), pi, 0.005 * pi);
  EXPECT_NEAR(area(make_rectangle_patch(Vec3::Zero(), Vec3(2, 0, 0), Vec3(0, 1, 0), 0.1)), 2.0,
              1e-12);
  EXPECT_NEAR(area(make_cylinder(Vec3::Zero(), Vec3::UnitZ(), 0.5, 2.0, 0.05)), 2 * pi * 0.5 * 2.0,
              0.005 * 2 * pi);
  EXPECT_NEAR(area(make_torus(Vec3::Zero(), Vec3::UnitZ(), 1.0, 0.25, 0.05)), 4 * pi * pi * 0.25,
              0.005 * 4 * pi * pi * 0.25);
  SurfaceMesh sphere = make_ellipsoid(Vec3::Zero(), Vec3::Constant(2.0), 0.2);
  EXPECT_LE(longest_edge(sphere), 0.2 + 1e-12);
  for (const auto& v : sphere.vertices) EXPECT_NEAR(v.norm(), 2.0, 1e-12);
}

TEST(SurfaceMeshes, PartsOfAnEllipsoidEndOnTheirCuttingPlanes) {
  auto area = [](const SurfaceMesh& m) {
    double a = 0.0;
    for (double v : vertex_areas(m)) a += v;
    return a;
  };
  // An eighth of a sphere of radius 0.5 about the origin.
  const SurfaceMesh eighth =
      make_ellipsoid_part(Vec3::Zero(), Vec3::Constant(0.5), 0.025, {1, 1, 1});
  EXPECT_LE(longest_edge(eighth), 0.025 + 1e-12);
  EXPECT_NEAR(area(eighth), pi * 0.25 / 2, 0.005 * pi * 0.25 / 2);
  // Every edge used by one triangle lies in one of the three planes, and every vertex is on
  // the sphere in the kept octant.
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : eighth.triangles)
    for (int e = 0; e < 3; ++e) ++uses[std::minmax(t[e], t[(e + 1) % 3])];
  int boundary = 0;
  for (const auto& [edge, count] : uses) {
    if (count != 1) continue;
    ++boundary;
    const Vec3 &a = eighth.vertices[edge.first], &b = eighth.vertices[edge.second];
    bool on_a_plane = false;
    for (int d = 0; d < 3; ++d) on_a_plane = on_a_plane || (a[d] == 0.0 && b[d] == 0.0);
    EXPECT_TRUE(on_a_plane) << a.transpose() << " – " << b.transpose();
  }
  EXPECT_GT(boundary, 3 * 30);  // three quarter circles of length π/4 at spacing ≤ 0.025
  for (const auto& v : eighth.vertices) {
    EXPECT_NEAR(v.norm(), 0.5, 1e-12);
    EXPECT_GE(v.minCoeff(), 0.0);
  }
  // Normals face out: the signed volume (1/3) Σ x·n dA of the closed eighth is +π R³ / 6.
  double volume = 0.0;
  for (const auto& t : eighth.triangles)
    volume += eighth.vertices[t[0]].dot(eighth.vertices[t[1]].cross(eighth.vertices[t[2]])) / 6;
  EXPECT_NEAR(volume, pi * 0.125 / 6, 0.01 * pi * 0.125 / 6);
  // A quarter of an oblate spheroid (x ≥ 0, y ≤ 0), as an airbag's quarter model.
  const Vec3 axes(0.29, 0.29, 0.1575);
  const SurfaceMesh quarter = make_ellipsoid_part(Vec3(0, 0, 1), axes, 0.01, {1, -1, 0});
  const double e = std::sqrt(1 - axes.z() * axes.z() / (axes.x() * axes.x()));
  const double full =
      2 * pi * axes.x() * axes.x() + pi * axes.z() * axes.z() / e * std::log((1 + e) / (1 - e));
  EXPECT_NEAR(area(quarter), full / 4, 0.005 * full / 4);
  for (const auto& v : quarter.vertices) {
    EXPECT_GE(v.x(), 0.0);
    EXPECT_LE(v.y(), 0.0);
    EXPECT_NEAR((v - Vec3(0, 0, 1)).cwiseQuotient(axes).norm(), 1.0, 1e-12);
  }
}

class MeshFiles : public ::testing::Test {
 protected:
  // One directory per test: ctest runs the tests of this fixture side by side.
  std::filesystem::path dir;
  void SetUp() override {
    dir = std::filesystem::temp_directory_path() /
          ("pellicle_mesh_files_" +
           std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::create_directories(dir);
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
  }
};

TEST_F(MeshFiles, AsciiStlBinaryStlAndObjGiveTheSameSquare) {
  write("square.stl",
        "solid sq\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
        "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\n"
        "vertex 0 1 0\nendloop\nendfacet\nendsolid sq\n");
  std::string binary(84, '\0');
  const std::uint32_t count = 2;
  std::memcpy(&binary[80], &count, 4);
  const float tris[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 0},
                             {0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 0}};
  for (const auto& t : tris) {
    binary.append(reinterpret_cast<const char*>(t), 48);
    binary.append(2, '\0');
  }
  write("square_binary.stl", binary);
  write("square.obj", "# a square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  for (const char* name : {"square.stl", "square_binary.stl", "square.obj"}) {
    const std::string path = (dir / name).string();
    const SurfaceMesh m = std::string(name).ends_with(".obj") ? read_obj(path) : read_stl(path);
    EXPECT_EQ(m.vertices.size(), 4u) << name;  // shared corners merged
    EXPECT_EQ(m.triangles.size(), 2u) << name;
    double a = 0.0;
    for (double v : vertex_areas(m)) a += v;
    EXPECT_NEAR(a, 1.0, 1e-6) << name;
  }
}

TEST_F(MeshFiles, MalformedFilesNameFileAndLine) {
  write("bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
  try {
    read_obj((dir / "bad.obj").string());
    FAIL() << "accepted a face with an undefined vertex";
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("bad.obj:3:1: face refers to vertex 7, which is not defined"),
        std::string::npos)
        << e.what();
  }
  EXPECT_THROW(read_stl((dir / "missing.stl").string()), InputError);
}

TEST(Frames, CurveTangentsFollowTheCircle) {
  // Thesis eq 7.1 on a closed circle: tangents along x_{p+1} − x_{p−1} are exact in
  // direction by symmetry; normals are the tangents turned +90°.
  const SampledCurve c = sample_ellipse_arc(Vec2::Zero(), Vec2::Ones(), 0.0, 2 * pi, {0.0, 64});
  FrameSetup<2> setup;
  setup.connectivity.closed_curve = true;
  auto estimator = make_connectivity_estimator<2>(setup);
  std::vector<Vec2> normal(c.points.size()), tangent(c.points.size());
  estimator->estimate(c.points, 0, static_cast<long>(c.points.size()), normal, tangent);
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    EXPECT_NEAR(std::abs(normal[i].dot(c.points[i])), 1.0, 1e-12);
    EXPECT_NEAR(tangent[i].dot(c.points[i]), 0.0, 1e-12);
  }
}

TEST(Frames, MeshNormalsOfASphereAreRadial) {
  const SurfaceMesh m = make_ellipsoid(Vec3::Zero(), Vec3::Ones(), 0.1);
  FrameSetup<3> setup;
  setup.connectivity.triangles = m.triangles;
  auto estimator = make_connectivity_estimator<3>(setup);
  std::vector<Vec3> normal(m.vertices.size()), tangent(m.vertices.size(), Vec3::Zero());
  estimator->estimate(m.vertices, 0, static_cast<long>(m.vertices.size()), normal, tangent);
  double worst = 0.0;
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    worst = std::max(worst, std::acos(std::min(1.0, normal[i].dot(m.vertices[i]))));
    EXPECT_NEAR(tangent[i].dot(normal[i]), 0.0, 1e-12);
    EXPECT_NEAR(tangent[i].norm(), 1.0, 1e-12);
  }
  EXPECT_LT(worst * 180 / pi, 1.0);  // outward, within a degree at spacing 0.1
}

}  // namespace
}  // namespace pellicle
