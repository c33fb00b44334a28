// Settling the sign of unsigned normals: propagation through neighbours, outward from the
// centroid, and keeping the side of the previous normal; 2D tangents follow the normal.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "pellicle/normals/frame_estimator.hpp"

namespace pellicle {
namespace {

std::vector<Vec2> circle(int n) {
  std::vector<Vec2> x;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    x.emplace_back(5 + 2 * std::cos(a), 5 + 2 * std::sin(a));
  }
  return x;
}

// Radial normals with random signs, as the isosurface method may return them.
std::vector<Vec2> scrambled(const std::vector<Vec2>& x) {
  std::mt19937 rng(4);
  std::vector<Vec2> n;
  for (const auto& p : x) n.push_back((rng() % 2 ? 1.0 : -1.0) * (p - Vec2(5, 5)).normalized());
  return n;
}

TEST(Orientation, PropagationMakesNeighboursAgree) {
  const auto x = circle(200);
  auto n = scrambled(x);
  std::vector<Vec2> t(x.size()), none(x.size(), Vec2::Zero());
  complete_frames<2>(x, 0, 200, NormalOrientation::propagate, none, n, t, 0.5);
  for (int k = 0; k < 200; ++k) {
    EXPECT_GT(n[k].dot(n[(k + 1) % 200]), 0.9) << k;  // one consistent side
    EXPECT_NEAR(t[k].x(), n[k].y(), 1e-15);           // n is t turned +90°
    EXPECT_NEAR(t[k].y(), -n[k].x(), 1e-15);
  }
}

TEST(Orientation, OutwardFromTheCentroid) {
  const auto x = circle(100);
  auto n = scrambled(x);
  std::vector<Vec2> t(x.size()), none(x.size(), Vec2::Zero());
  complete_frames<2>(x, 0, 100, NormalOrientation::outward, none, n, t, 0.5);
  for (int k = 0; k < 100; ++k) EXPECT_GT(n[k].dot(x[k] - Vec2(5, 5)), 0.0) << k;
}

TEST(Orientation, PreviousNormalsKeepTheirSide) {
  const auto x = circle(50);
  auto n = scrambled(x);
  std::vector<Vec2> previous(x.size()), t(x.size());
  for (int k = 0; k < 50; ++k) previous[k] = -(x[k] - Vec2(5, 5)).normalized();  // inward before
  complete_frames<2>(x, 0, 50, NormalOrientation::outward, previous, n, t, 0.5);
  for (int k = 0; k < 50; ++k) EXPECT_LT(n[k].dot(x[k] - Vec2(5, 5)), 0.0) << k;  // still inward
}

TEST(Orientation, ThreeDTangentsAreContinued) {
  std::vector<Vec3> x{Vec3(0, 0, 0)}, n{Vec3(0, 0.1, 1).normalized()}, t{Vec3(1, 0, 0)},
      prev{Vec3(0, 0, 1)};
  complete_frames<3>(x, 0, 1, NormalOrientation::propagate, prev, n, t, 1.0);
  EXPECT_NEAR(t[0].dot(n[0]), 0.0, 1e-15);
  EXPECT_NEAR(t[0].norm(), 1.0, 1e-15);
  EXPECT_GT(t[0].x(), 0.99);  // stays close to the previous t1
}

TEST(Orientation, EnclosedPointsWithinACellOfTheMembraneDecideEverySide) {
  // A circle of membrane points and a disk of enclosed points around it (some inside, some
  // beyond it): the sides found from the points WithinACell keeps equal those found from all.
  const double cell = 0.25;
  const std::vector<Vec2> x = circle(120);
  const std::vector<Vec2> normal = scrambled(x);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(2.0, 8.0);
  std::vector<Vec2> all, kept;
  const WithinACell<2> near(x, 0, static_cast<long>(x.size()), cell);
  for (int k = 0; k < 20000; ++k) {
    const Vec2 y(coordinate(rng), coordinate(rng));
    all.push_back(y);
    if (near(y)) kept.push_back(y);
  }
  EXPECT_LT(kept.size(), all.size() / 2);
  EXPECT_GT(kept.size(), 0u);
  const long n = static_cast<long>(x.size());
  EXPECT_EQ(sides_from_inside<2>(x, 0, n, normal, kept, cell),
            sides_from_inside<2>(x, 0, n, normal, all, cell));
  // A point just beyond a cell of every membrane point is not kept; one just within is.
  const Vec2 centre(5, 5);
  EXPECT_FALSE(near(centre));
  EXPECT_TRUE(near(x[0] + Vec2(0, 0.999 * cell)));
  EXPECT_FALSE(near(Vec2(5 + 2 + 1.001 * cell, 5)));
}

}  // namespace
}  // namespace pellicle
