// Contact between point-cloud surfaces (Suchde & Kuhnert §3.6): the signed distance of
// eq 10 against exact distances, the split of neighbourhoods into S_i and S_i^ext, chambers
// relabelled by connected components, and the three responses on two sheets that cross.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pellicle/pointcloud/local_frame.hpp"
#include "pellicle/surface/chambers.hpp"
#include "pellicle/surface/contact.hpp"
#include "pellicle/surface/gfdm.hpp"
#include "pellicle/surface/signed_distance.hpp"
#include "support/test_clouds.hpp"

namespace pellicle {
namespace {

//! Points of the unit sphere within `radius` of the north pole, with outward normals.
void sphere_cap(double radius, std::vector<Vec3>& x, std::vector<Vec3>& n) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-radius, radius);
  x.clear();
  n.clear();
  while (x.size() < 20) {
    const Vec3 p = Vec3(u(rng), u(rng), 1.0).normalized();
    if ((p - Vec3::UnitZ()).norm() > radius) continue;
    x.push_back(p);
    n.push_back(p);
  }
  // The nearest to the points asked about below first.
  std::swap(x[0], *std::min_element(x.begin(), x.end(), [](const Vec3& a, const Vec3& b) {
              return (a - Vec3::UnitZ()).norm() < (b - Vec3::UnitZ()).norm();
            }));
  n = x;
}

TEST(SignedDistance, FollowsTheDistanceToASphereFromItsPoints) {
  std::vector<Vec3> x, n;
  sphere_cap(0.1, x, n);
  // Exact: |y| − 1, positive outside (the normals' side). The quadratic fit is exact to
  // second order in the offset across the patch (0.1): errors of a few 1e-4.
  for (const Vec3& y : {Vec3(0.0, 0.0, 1.03), Vec3(0.02, -0.03, 0.97), Vec3(0.05, 0.02, 1.01),
                        Vec3(-0.04, 0.0, 0.99)}) {
    const SignedDistance<3> d = signed_distance<3>(y, x.data(), n.data(), 20, 0.01);
    ASSERT_TRUE(d.valid);
    EXPECT_NEAR(d.distance, y.norm() - 1.0, 5e-4) << y.transpose();
    EXPECT_GT(d.direction.dot(y.normalized()), 0.999);
  }
}

TEST(SignedDistance, OnePointGivesItsTangentPlane) {
  const Vec3 x0(1.0, 2.0, 3.0), n0 = Vec3(1.0, 1.0, 0.0).normalized();
  const Vec3 y = x0 + 0.3 * n0 + Vec3(0.0, 0.0, 0.5);
  const SignedDistance<3> d = signed_distance<3>(y, &x0, &n0, 1, 0.01);
  ASSERT_TRUE(d.valid);
  EXPECT_NEAR(d.distance, 0.3, 1e-12);
  EXPECT_NEAR((d.direction - n0).norm(), 0.0, 1e-12);
}

TEST(SignedDistance, CurvesIn2DFollowTheCircle) {
  std::vector<Vec2> x, n;
  for (int k = -4; k <= 4; ++k) {
    const double a = 0.5 * M_PI + 0.02 * k;
    x.emplace_back(std::cos(a), std::sin(a));
  }
  std::swap(x[0], x[4]);  // (0, 1) first
  n = x;
  const Vec2 y(0.01, 1.02);
  const SignedDistance<2> d = signed_distance<2>(y, x.data(), n.data(), 9, 0.005);
  ASSERT_TRUE(d.valid);
  EXPECT_NEAR(d.distance, y.norm() - 1.0, 2e-4);
}

//! Two parallel square sheets z = ∓gap/2, chamber 0 below and 1 above, normals +z both.
PointCloud<3> two_sheets(double gap, double h) {
  PointCloud<3> c = test::random_patch(400, h, 0.0, 3);
  PointCloud<3> upper = test::random_patch(400, h, 0.0, 4);
  for (std::size_t i = 0; i < c.size(); ++i) c.position[i].z() = -0.5 * gap;
  for (std::size_t i = 0; i < upper.size(); ++i) {
    const std::size_t k = c.add_point(upper.position[i] + Vec3(0, 0, 0.5 * gap), h, false);
    c.chamber[k] = c.surface[k] = 1;
  }
  return c;
}

TEST(Chambers, NeighbourhoodsHoldTheirOwnChamberAndTheRestIsExternal) {
  const double h = 0.2;
  PointCloud<3> c = two_sheets(0.05, h);
  NeighbourSearch<3> search;
  NeighbourLists own, external;
  search.find(c, own);
  const std::size_t all = own.index.size();
  ASSERT_TRUE(c.has_parts());
  split_by_part(c, own, &external);
  EXPECT_EQ(own.index.size() + external.index.size(), all);
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_EQ(own.index[own.begin(i)], static_cast<int>(i));  // itself first
    for (long k = own.begin(i); k < own.end(i); ++k)
      EXPECT_EQ(c.chamber[own.index[k]], c.chamber[i]);
    for (long k = external.begin(i); k < external.end(i); ++k)
      EXPECT_NE(c.chamber[external.index[k]], c.chamber[i]);
  }
  EXPECT_GT(external.index.size(), 0u);
}

TEST(Chambers, FacingNormalsSplitOneChamberWhenSelfContactIsOn) {
  PointCloud<3> c = two_sheets(0.05, 0.2);
  for (std::size_t i = 0; i < c.size(); ++i) {
    c.chamber[i] = 0;
    if (c.position[i].z() > 0) c.frame[i].col(2) = -c.frame[i].col(2);  // facing down
  }
  NeighbourSearch<3> search;
  NeighbourLists lists, external;
  search.find(c, lists);
  NeighbourLists unsplit = lists;
  EXPECT_FALSE(c.has_parts());  // self-contact off: one part
  c.facing_limit = -0.5;
  ASSERT_TRUE(c.has_parts());
  split_by_part(c, lists, &external);
  long across = 0;
  for (std::size_t i = 0; i < c.size(); ++i)
    for (long k = lists.begin(i); k < lists.end(i); ++k)
      across += (c.position[lists.index[k]].z() > 0) != (c.position[i].z() > 0);
  EXPECT_EQ(across, 0);
  EXPECT_EQ(lists.index.size() + external.index.size(), unsplit.index.size());
}

TEST(Chambers, AChamberThatComesApartIsSplitLargestKeepingItsId) {
  const double h = 0.2;
  PointCloud<3> c = test::jittered_sphere(1.0, h);
  const std::size_t first = c.size();
  const PointCloud<3> small = test::jittered_sphere(0.5, h, 6.0, 9);
  for (const Vec3& x : small.position) c.add_point(x + Vec3(3.0, 0.0, 0.0), h, false);
  for (int& id : c.chamber) id = 4;
  NeighbourSearch<3> search;
  NeighbourLists own, external;
  search.find(c, own);
  external.offset.assign(c.size() + 1, 0);
  EXPECT_EQ(split_chambers(c, own, external).split, 1);
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_EQ(c.chamber[i], i < first ? 4 : 5);
  EXPECT_EQ(c.chamber_count(), 2);
  EXPECT_EQ(split_chambers(c, own, external).split, 0);  // nothing left to split
}

TEST(Chambers, PiecesSmallerThanTheSmallestPartAreRemoved) {
  const double h = 0.2;
  PointCloud<3> c = test::jittered_sphere(1.0, h);
  const std::size_t sphere = c.size();
  for (int k = 0; k < 3; ++k) c.add_point(Vec3(3.0 + 0.05 * k, 0.0, 0.0), h, false);  // debris
  NeighbourSearch<3> search;
  NeighbourLists own, external;
  search.find(c, own);
  external.offset.assign(c.size() + 1, 0);
  const ChamberReport r = split_chambers(c, own, external, 11);
  EXPECT_EQ(r.debris, 3);
  EXPECT_EQ(r.split, 0);
  EXPECT_EQ(c.size(), sphere);
  EXPECT_EQ(c.chamber_count(), 1);
}

// A sheet folded back onto itself along x = 0, as eq 52 leaves a band it crushes: the lower
// half z = −0.02 (normals −z) and the upper z = +0.02 (normals +z), both x ≤ 0, one chamber.
// With self-contact the halves are two parts, and the points near x = 0 have one-sided
// neighbourhoods. Every Laplacian must still have a negative centre (a stable implicit row:
// the fold's stencil, zero flux across the rim) and stay exact for quadratics with no slope
// at the point, whose flux across the rim is zero: Δ((x − x_i)² + (y − y_i)²) = 4.
TEST(Folds, PointsOnTheRimOfTheirPartGetStableLaplacians) {
  const double h = 0.2;
  PointCloud<3> c;
  for (const int side : {-1, 1}) {  // about 30 points within h
    const PointCloud<3> sheet = test::random_patch(1000, h, 0.0, side > 0 ? 4 : 3);
    for (const Vec3& x : sheet.position) {
      if (x.x() > 0.0) continue;
      const std::size_t k = c.add_point(Vec3(x.x(), x.y(), 0.02 * side), h, false);
      if (side < 0) flip_normal<3>(c.frame[k]);
    }
  }
  c.facing_limit = 0.0;
  ASSERT_TRUE(c.has_parts());
  NeighbourSearch<3> search;
  NeighbourLists own, external;
  search.find(c, own);
  split_by_part(c, own, &external);
  SurfaceStencils<3> st;
  build_stencils<3>(c, own, GfdmOptions{}, st);
  int rim = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_LT(st.laplacian[own.begin(i)], 0.0)
        << "point " << i << " at " << c.position[i].transpose();
    double quadratic = 0.0;
    for (long k = own.begin(i); k < own.end(i); ++k) {
      const Vec3 d = c.position[own.index[k]] - c.position[i];
      quadratic += st.laplacian[k] * (d.x() * d.x() + d.y() * d.y());
    }
    EXPECT_NEAR(quadratic, 4.0, 1e-8) << "point " << i;
    rim += c.position[i].x() > -0.25 * h && std::abs(c.position[i].y()) < 0.8;
  }
  EXPECT_GT(rim, 20);  // the rim is there to test
}

//! Two sheets after a step in which they crossed: sheet 0 was below (side −1 against the
//! upper sheet's +z normals), now at z = +d; sheet 1 was above, now at z = −d.
struct Crossed {
  PointCloud<3> cloud;
  NeighbourLists own, external;
  explicit Crossed(double d) : cloud(two_sheets(-2.0 * d, 0.3)) {
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      cloud.contact_side[i] = cloud.chamber[i] == 0 ? -1 : 1;
      cloud.velocity[i] = Vec3(0, 0, cloud.chamber[i] == 0 ? 1.0 : -1.0);
    }
    NeighbourSearch<3> search;
    search.find(cloud, own);
    split_by_part(cloud, own, &external);
  }
};

TEST(ContactResponses, NonPenetrationPutsCrossedSheetsBackInOrder) {
  Crossed s(0.01);
  ContactOptions o;
  o.between = ContactResponse::non_penetration;
  const ContactReport r = resolve_contacts(s.cloud, s.own, s.external, o, 0.2);
  EXPECT_GT(r.penetrated, 0);
  EXPECT_EQ(r.projected, r.penetrated);
  EXPECT_EQ(r.removed, 0);
  // Every point at least h inside the squares (28 points of the other sheet within h on
  // average) (the other sheet's points all around it) is
  // back on its side, ξ off the other sheet's plane; velocities averaged to zero across.
  long checked = 0;
  for (std::size_t i = 0; i < s.cloud.size(); ++i) {
    if (s.cloud.position[i].head<2>().lpNorm<Eigen::Infinity>() > 0.7) continue;
    ++checked;
    const double z = s.cloud.position[i].z();
    if (s.cloud.chamber[i] == 0)
      EXPECT_LT(z, -0.01) << i;
    else
      EXPECT_GT(z, 0.01) << i;
    EXPECT_NEAR(s.cloud.velocity[i].z(), 0.0, 1e-12);
  }
  EXPECT_GT(checked, 350);
  EXPECT_EQ(s.cloud.chamber_count(), 2);
}

TEST(ContactResponses, DeleteRemovesPenetratedPointsAndJoinsTheChambers) {
  Crossed s(0.01);
  ContactOptions o;
  o.between = ContactResponse::remove;
  const std::size_t before = s.cloud.size();
  const ContactReport r = resolve_contacts(s.cloud, s.own, s.external, o, 0.2);
  EXPECT_EQ(static_cast<std::size_t>(r.removed), before - s.cloud.size());
  EXPECT_GT(r.removed, 350);  // at least every point h inside the squares
  EXPECT_EQ(r.joined, 1);
  EXPECT_EQ(s.cloud.chamber_count(), 1);
}

TEST(ContactResponses, MergeJoinsPointsPairwiseIntoOneWall) {
  Crossed s(0.01);
  ContactOptions o;
  o.rules.push_back({0, 1, ContactResponse::merge});
  const std::size_t before = s.cloud.size();
  const ContactReport r = resolve_contacts(s.cloud, s.own, s.external, o, 0.2);
  EXPECT_GT(r.removed, 150);                                   // about one per pair
  EXPECT_LE(2 * static_cast<std::size_t>(r.removed), before);  // at most one per pair
  EXPECT_EQ(s.cloud.size(), before - r.removed);
  EXPECT_EQ(s.cloud.chamber_count(), 1);
}

TEST(ContactResponses, NoneOnlyRecordsTheSide) {
  Crossed s(0.01);
  const std::vector<Vec3> x = s.cloud.position;
  const ContactReport r = resolve_contacts(s.cloud, s.own, s.external, ContactOptions{}, 0.2);
  EXPECT_GT(r.penetrated, 0);
  EXPECT_EQ(r.projected + r.removed, 0);
  EXPECT_EQ(s.cloud.position, x);
  for (std::size_t i = 0; i < s.cloud.size(); ++i) {
    if (s.cloud.position[i].head<2>().lpNorm<Eigen::Infinity>() < 0.7) {
      EXPECT_EQ(s.cloud.contact_side[i], s.cloud.chamber[i] == 0 ? 1 : -1);
    }
  }
}

}  // namespace
}  // namespace pellicle
