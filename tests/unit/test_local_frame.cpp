// One frame type for membranes and surfaces (pointcloud/local_frame.hpp): the conversions
// between a surface's frame matrix and a membrane's (normal, tangent) pair are exact and give
// right-handed orthonormal frames, and each side's estimators fill the other's frames — PCA
// (normals/) on a surface cloud of a sphere, the surfaces' eq 4 (Suchde & Kuhnert §3.2) on a
// membrane's points round a circle — as accurately as their own do.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <numbers>
#include <random>

#include "pellicle/normals/frame_estimator.hpp"
#include "pellicle/pointcloud/local_frame.hpp"
#include "pellicle/pointcloud/neighbour_search.hpp"
#include "pellicle/surface/estimator_frames.hpp"
#include "pellicle/surface/frames.hpp"
#include "support/test_clouds.hpp"

namespace pellicle {
namespace {

template <int D>
std::unique_ptr<FrameEstimator<D>> estimator(const std::string& name, const FrameSetup<D>& setup) {
  for (const auto& choice : frame_estimators<D>())
    if (choice.name == name) return choice.make(setup);
  return nullptr;
}

template <int D>
void expect_right_handed(const Mat<D>& f) {
  EXPECT_LT((f.transpose() * f - Mat<D>::Identity()).norm(), 1e-12);
  EXPECT_NEAR(f.determinant(), 1.0, 1e-12);
}

TEST(LocalFrame, PairAndMatrixConvertExactly) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int k = 0; k < 100; ++k) {
    const Vec3 n = Vec3(g(rng), g(rng), g(rng)).normalized();
    const Vec3 hint(g(rng), g(rng), g(rng));
    const Vec3 t = tangent_in_plane(n, hint);
    const Mat3 f = frame_of<3>(n, t);
    expect_right_handed<3>(f);
    EXPECT_EQ(normal_of<3>(f), n);
    EXPECT_EQ(tangent_of<3>(f), t);
    EXPECT_EQ(frame_from<3>(n, hint), f);
    // Off the normal the membranes' and the surfaces' tangent rules are the same projection.
    EXPECT_EQ(continue_tangent(hint, n), t);
    Mat3 flipped = f;
    flip_normal<3>(flipped);
    expect_right_handed<3>(flipped);
    EXPECT_EQ(normal_of<3>(flipped), Vec3(-n));

    const Vec2 n2 = Vec2(g(rng), g(rng)).normalized();
    const Mat<2> f2 = frame_of<2>(n2, Vec2::Zero());
    expect_right_handed<2>(f2);
    const Vec2 t2 = tangent_of<2>(f2);
    EXPECT_EQ(Vec2(-t2.y(), t2.x()), n2);  // the membranes' 2D rule: n is t turned +90°
  }
  // Along the normal both rules still give a unit tangent in the plane.
  const Vec3 n = Vec3::UnitX();
  for (const Vec3& t : {tangent_in_plane(n, n), continue_tangent(n, n)}) {
    EXPECT_NEAR(t.norm(), 1.0, 1e-15);
    EXPECT_NEAR(t.dot(n), 0.0, 1e-15);
  }
}

//! Largest angle between the frames' normals and the given unit normals.
template <int D>
double worst_angle(const PointCloud<D>& c, const std::vector<Vec<D>>& exact) {
  double worst = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i)
    worst = std::max(worst, std::acos(std::min(1.0, normal_of<D>(c.frame[i]).dot(exact[i]))));
  return worst;
}

TEST(EstimatorFrames, MembranePcaGivesASurfaceCloudItsFrames) {
  auto c = test::jittered_sphere(1.0, 0.2);
  std::vector<Vec3> exact(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) exact[i] = c.position[i].normalized();
  FrameSetup<3> setup;
  setup.cell = 0.2;
  setup.orientation = FrameOrientation<3>(NormalOrientation::outward);
  const auto pca = estimator<3>("pca", setup);
  ASSERT_TRUE(pca);
  estimate_frames<3>(*pca, c, false);
  for (const auto& f : c.frame) expect_right_handed<3>(f);
  const double by_pca = worst_angle(c, exact);

  auto eq4 = test::jittered_sphere(1.0, 0.2);
  NeighbourSearch<3> search;
  NeighbourLists nb;
  search.find(eq4, nb);
  estimate_frames(eq4, nb, FrameOptions{}, false);
  orient_consistently(eq4, nb);
  const double by_eq4 = worst_angle(eq4, exact);
  // Both outward (an inward normal is π off) and within a few degrees on a cap of radius h.
  EXPECT_LT(by_pca, 0.05);
  EXPECT_LT(by_eq4, 0.05);

  // Again, keeping sides: the frames do not move and their tangents are continued.
  const auto before = c.frame;
  estimate_frames<3>(*pca, c, true);
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_LT((c.frame[i] - before[i]).norm(), 1e-12);
}

TEST(EstimatorFrames, SurfaceFramesGiveAMembraneItsNormalsAndTangents) {
  // A membrane's points round a circle, in order: the connectivity estimator's (n, t) against
  // the surfaces' eq 4 frames of the same points, taken apart into (n, t).
  constexpr int kPoints = 200;
  const double radius = 1.0, spacing = 2 * std::numbers::pi * radius / kPoints;
  std::vector<Vec2> x(kPoints);
  for (int k = 0; k < kPoints; ++k) {
    const double a = 2 * std::numbers::pi * k / kPoints;
    x[k] = radius * Vec2(std::cos(a), std::sin(a));
  }
  FrameSetup<2> setup;
  setup.cell = 4 * spacing;
  setup.connectivity.closed_curve = true;
  setup.orientation = FrameOrientation<2>(NormalOrientation::outward);
  const auto connectivity = estimator<2>("connectivity", setup);
  std::vector<Vec2> normal(kPoints, Vec2::Zero()), tangent(kPoints, Vec2::Zero());
  connectivity->estimate(x, 0, kPoints, normal, tangent);

  PointCloud<2> c;
  for (const auto& p : x) c.add_point(p, 3.5 * spacing, false);
  NeighbourSearch<2> search;
  NeighbourLists nb;
  search.find(c, nb);
  estimate_frames(c, nb, FrameOptions{}, false);
  orient_consistently(c, nb, &normal);
  for (int k = 0; k < kPoints; ++k) {
    const Vec2 n = normal_of<2>(c.frame[k]), t = tangent_of<2>(c.frame[k]);
    EXPECT_LT((n - normal[k]).norm(), 1e-12) << k;  // a uniform circle: both exact
    EXPECT_LT((t - tangent[k]).norm(), 1e-12) << k;
    EXPECT_NEAR(std::abs(n.dot(x[k])) / radius, 1.0, 1e-12) << k;
  }
}

}  // namespace
}  // namespace pellicle
