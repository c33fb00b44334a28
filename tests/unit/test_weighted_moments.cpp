// The weighted second moments whose least eigenvector is a normal (pointcloud/
// weighted_moments.hpp): centred, they are the weighted covariance about the weighted mean
// (the membranes' principal directions); uncentred with w = W/|d|², Suchde & Kuhnert's eq 4
// matrix. Points scattered about a tilted plane give its normal.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pellicle/pointcloud/weighted_moments.hpp"
#include "pellicle/pointcloud/weights.hpp"

namespace pellicle {
namespace {

TEST(WeightedMoments, CentredMomentsAreTheWeightedCovariance) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> d(40);
  std::vector<double> w(d.size());
  for (std::size_t k = 0; k < d.size(); ++k) d[k] = Vec3(u(rng), u(rng), u(rng)), w[k] = 1 + u(rng);
  WeightedMoments<3, true> centred;
  WeightedMoments<3, false> plain;
  Vec3 mean = Vec3::Zero();
  double total = 0.0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    centred.add(d[k], w[k]), plain.add(d[k], w[k]);
    mean += w[k] * d[k], total += w[k];
  }
  mean /= total;
  Mat3 covariance = Mat3::Zero(), second = Mat3::Zero();
  for (std::size_t k = 0; k < d.size(); ++k) {
    covariance += w[k] * (d[k] - mean) * (d[k] - mean).transpose() / total;
    second += w[k] * d[k] * d[k].transpose();
  }
  EXPECT_LT((centred.matrix() - covariance).norm(), 1e-13);
  EXPECT_LT((plain.matrix() - second).norm(), 1e-13);
}

TEST(WeightedMoments, LeastSpreadOfPointsNearAPlaneIsItsNormal) {
  const Vec3 normal = Vec3(1.0, -2.0, 0.5).normalized();
  const Vec3 a = normal.unitOrthogonal(), b = normal.cross(a);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  WeightedMoments<3, true> centred;
  WeightedMoments<3, false> eq4;
  for (int k = 0; k < 200; ++k) {
    const Vec3 d = u(rng) * a + u(rng) * b + 1e-3 * u(rng) * normal;
    const double s = d.squaredNorm() / 2.0;
    centred.add(d, compact_weight(s));
    eq4.add(d, gaussian_weight(d.squaredNorm(), 1.0, 2.0) / d.squaredNorm());
  }
  for (const Vec3& n :
       {least_spread_direction<3>(centred.matrix()), least_spread_direction<3>(eq4.matrix())}) {
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_GT(std::abs(n.dot(normal)), 1.0 - 1e-5);  // within about 0.26°
  }
}

}  // namespace
}  // namespace pellicle
