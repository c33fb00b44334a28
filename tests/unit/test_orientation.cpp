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

}  // namespace
}  // namespace pellicle
