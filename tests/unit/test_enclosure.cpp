// The inside of a membrane (geometry/enclosure): closed curves and surfaces, and ones closed
// by the symmetry planes their ends lie on.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pellicle/geometry/curve.hpp"
#include "pellicle/geometry/enclosure.hpp"
#include "pellicle/geometry/fill.hpp"
#include "pellicle/geometry/surface_mesh.hpp"

namespace pellicle {
namespace {

Enclosure<2> arc(double from, double to, const std::vector<MirrorPlane>& planes) {
  const SampledCurve c = sample_ellipse_arc({0, 0}, {0.5, 0.5}, from, to, {0.0, 91});
  MembraneConnectivity connectivity;
  connectivity.closed_curve = c.closed;
  return Enclosure<2>(c.points, 0, static_cast<long>(c.points.size()), connectivity, planes, 0.01);
}

TEST(Enclosure, QuarterArcIsClosedByTheTwoSymmetryPlanes) {
  const auto quarter = arc(0.0, std::numbers::pi / 2, {{0, 0.0}, {1, 0.0}});
  ASSERT_EQ(quarter.problem(), "");
  EXPECT_TRUE(quarter.inside({0.1, 0.1}));
  EXPECT_TRUE(quarter.inside({0.49, 0.01}));
  EXPECT_TRUE(quarter.inside({0.01, 0.3}));
  EXPECT_FALSE(quarter.inside({0.4, 0.4}));  // |x| = 0.57
  EXPECT_FALSE(quarter.inside({0.6, 0.0}));
  // Distances to the arc, not to the planes.
  EXPECT_NEAR(quarter.distance({0.1, 0.0}), 0.4, 1e-3);
  EXPECT_NEAR(quarter.distance({0.2, 0.2}), 0.5 - std::sqrt(0.08), 1e-3);
}

TEST(Enclosure, FillOfTheQuarterHasTheQuarterDiskArea) {
  auto quarter =
      std::make_shared<const Enclosure<2>>(arc(0.0, std::numbers::pi / 2, {{0, 0.0}, {1, 0.0}}));
  const auto region = make_enclosed_region<2>(quarter, 0.0);
  const auto points = fill_region<2>(*region, {0, 0}, {1, 1}, 0.01, 2);
  const double area = points.size() * 0.005 * 0.005;
  EXPECT_NEAR(area, std::numbers::pi * 0.25 / 4, 2e-3);  // lattice error ~ perimeter × spacing
  // A gap of 0.05 removes a band of that width along the arc only.
  const auto gapped = make_enclosed_region<2>(quarter, 0.05);
  const double gapped_area = fill_region<2>(*gapped, {0, 0}, {1, 1}, 0.01, 2).size() * 2.5e-5;
  EXPECT_NEAR(gapped_area, std::numbers::pi * 0.45 * 0.45 / 4, 2e-3);
}

TEST(Enclosure, OpenArcAwayFromEveryPlaneIsReported) {
  const auto quarter = arc(0.0, std::numbers::pi / 2, {{0, 0.0}});  // y = 0 is not a face
  EXPECT_NE(quarter.problem().find("open at (0.5, 0)"), std::string::npos) << quarter.problem();
  const auto full = arc(0.0, 2 * std::numbers::pi, {});
  EXPECT_EQ(full.problem(), "");
  EXPECT_TRUE(full.inside({-0.3, -0.3}));
  EXPECT_FALSE(full.inside({-0.4, -0.4}));
}

TEST(Enclosure, EighthOfASphereClosedByThreePlanesAndAWholeSphere) {
  const SurfaceMesh g = make_ellipsoid(Vec3::Zero(), Vec3::Ones(), 0.2);
  MembraneConnectivity all;
  all.triangles = g.triangles;
  const long n = static_cast<long>(g.vertices.size());
  const Enclosure<3> whole(g.vertices, 0, n, all, {}, 0.1);
  ASSERT_EQ(whole.problem(), "");
  EXPECT_TRUE(whole.inside({0.0, 0.0, 0.0}));
  EXPECT_TRUE(whole.inside({0.5, -0.5, 0.5}));
  EXPECT_FALSE(whole.inside({0.7, 0.7, 0.7}));
  EXPECT_FALSE(whole.inside({2.0, 0.0, 0.0}));
  // Keep the triangles in the octant x, y, z ≥ 0 and close them by the three planes.
  const std::vector<Vec3>& points = g.vertices;
  MembraneConnectivity octant;
  for (const auto& t : g.triangles) {
    bool keep = true;
    for (int k : t) keep = keep && (points[k].array() >= -1e-12).all();
    if (keep) octant.triangles.push_back(t);
  }
  const Enclosure<3> eighth(points, 0, n, octant, {{0, 0.0}, {1, 0.0}, {2, 0.0}}, 0.3);
  ASSERT_EQ(eighth.problem(), "") << eighth.problem();
  EXPECT_TRUE(eighth.inside({0.3, 0.3, 0.3}));
  EXPECT_TRUE(eighth.inside({0.9, 0.05, 0.05}));
  EXPECT_FALSE(eighth.inside({0.7, 0.7, 0.7}));
}

}  // namespace
}  // namespace pellicle
