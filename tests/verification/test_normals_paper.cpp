// The local isosurface method against Sulsky & York (2000): exactness where the interpolant
// can represent the surface (Tables I–II, Figs 4a, 5a, 9c–d, 11) and the paper's errors where
// it cannot (Table III, Figs 4b, 5b, 7, 10). Unit cells as in the paper.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "pellicle/normals/isosurface.hpp"

namespace pellicle {
namespace {

constexpr double pi = std::numbers::pi;

template <int D>
struct Result {
  double max_error = 0.0, rms_error = 0.0;  // radians, sign of the normal ignored
  double paper_rms = 0.0;  // sqrt(Σ e²)/n: the normalisation that reproduces Table III
  std::vector<double> condition;
};

template <int D>
Result<D> estimate(IsosurfaceBasis basis, const std::vector<Vec<D>>& points,
                   const std::vector<Vec<D>>& exact, const Vec<D>& origin, unsigned seed = 7) {
  FrameSetup<D> setup;
  setup.grid_origin = origin;
  setup.cell = 1.0;
  setup.seed = seed;
  IsosurfaceEstimator<D> estimator(setup, basis);
  std::vector<Vec<D>> normal(points.size());
  estimator.gradients(points, 0, static_cast<long>(points.size()), normal);
  Result<D> r;
  double sum = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    // atan2 keeps small angles accurate (acos cannot resolve below ~1e-8).
    const Vec<D> e = exact[i].normalized();
    const double along = std::abs(normal[i].dot(e));
    const double across = (normal[i] - normal[i].dot(e) * e).norm();
    const double angle = std::atan2(across, along);
    r.max_error = std::max(r.max_error, angle);
    sum += angle * angle;
  }
  r.rms_error = std::sqrt(sum / points.size());
  r.paper_rms = std::sqrt(sum) / points.size();
  r.condition = estimator.statistics().condition;
  return r;
}

TEST(NormalsPaper, LinesAreExactWithLinearShapeFunctions) {
  // Tables I and II: lines through the unit cell with slopes ±0.1 … ±10 by 3, 4 and 8 points,
  // 100 placements of the extra point each: exact normals.
  for (double slope : {0.1, 0.5, 1.0, 2.0, 10.0, -10.0, -2.0, -1.0, -0.5, -0.1}) {
    for (int n : {3, 4, 8}) {
      // The part of y − 0.5 = slope (x − 0.5) inside the cell, points at its interior fractions.
      const double half = std::min(0.5, 0.5 / std::abs(slope));
      std::vector<Vec2> points, exact;
      for (int k = 0; k < n; ++k) {
        const double dx = -half + 2 * half * (k + 0.5) / n * 0.98 + 0.01 * half;
        points.emplace_back(0.5 + dx, 0.5 + slope * dx);
        exact.emplace_back(-slope, 1.0);
      }
      std::vector<double> conditions;
      double worst = 0.0;
      for (unsigned seed = 1; seed <= 100; ++seed) {
        const auto r = estimate<2>(IsosurfaceBasis::linear, points, exact, Vec2::Zero(), seed);
        worst = std::max(worst, r.max_error);
        conditions.push_back(r.condition.front());
      }
      EXPECT_LT(worst, 1e-10) << "slope " << slope << ", " << n << " points";
      std::sort(conditions.begin(), conditions.end());
      if (n == 3)
        std::printf(
            "slope %5.1f, 3 points: condition of the normal equations min %.1e median %.1e "
            "max %.1e\n",
            slope, conditions.front(), conditions[50], conditions.back());
    }
  }
}

TEST(NormalsPaper, BilinearCurveIsExact) {
  // Fig 4a: three points on xy + 0.1x + 0.3 = 0 (a bilinear function): exact.
  std::vector<Vec2> points, exact;
  for (double x : {-0.9, -0.7, -0.5}) {
    const double y = -(0.1 * x + 0.3) / x;
    points.emplace_back(x, y);
    exact.emplace_back(y + 0.1, x);  // ∇(xy + 0.1x + 0.3)
  }
  EXPECT_LT(estimate<2>(IsosurfaceBasis::linear, points, exact, Vec2(-1, 0)).max_error, 1e-10);
}

TEST(NormalsPaper, CircleErrorsFollowTableIII) {
  // Table III: n points on the circle of radius 0.8 about the origin, in the unit cell. The
  // paper's numbers are reproduced with the points spread from 5° to 85° and its "rms" read
  // as sqrt(Σ e²)/n (the true rms, sqrt(Σ e²/n), levels off near 0.055 instead).
  const double paper_rms[] = {0.0571, 0.0434, 0.0231, 0.0141, 0.0092};
  const double paper_max[] = {0.1211, 0.1091, 0.1177, 0.1261, 0.1308};
  int row = 0;
  for (int n : {3, 4, 8, 16, 32}) {
    std::vector<Vec2> points, exact;
    for (int k = 0; k < n; ++k) {
      const double a = (5.0 + 80.0 * k / (n - 1)) * pi / 180;
      points.emplace_back(0.8 * std::cos(a), 0.8 * std::sin(a));
      exact.push_back(points.back());
    }
    const auto r = estimate<2>(IsosurfaceBasis::linear, points, exact, Vec2::Zero());
    std::printf("circle, %2d points: max %.4f, sqrt(Σe²)/n %.4f, rms %.4f rad (paper %.4f, %.4f)\n",
                n, r.max_error, r.paper_rms, r.rms_error, paper_max[row], paper_rms[row]);
    EXPECT_NEAR(r.max_error, paper_max[row], 0.15 * paper_max[row]) << n;
    EXPECT_NEAR(r.paper_rms, paper_rms[row], 0.2 * paper_rms[row]) << n;
    ++row;
  }
}

TEST(NormalsPaper, ArcWithSharedCoordinatesDefeatsLinearButNotQuadratic) {
  // Fig 7: arc (x−0.5)² + (y−0.5)² = 0.3²; (a) distinct coordinates: about 6°; (b) pairs with
  // the same y: about 34° (the x-component of a linear ∇χ depends on y only). Fig 9c–d:
  // quadratic B-splines with 8 points are exact.
  auto arc = [](const std::vector<double>& degrees) {
    std::pair<std::vector<Vec2>, std::vector<Vec2>> out;
    for (double d : degrees) {
      const Vec2 r(std::cos(d * pi / 180), std::sin(d * pi / 180));
      out.first.push_back(Vec2(0.5, 0.5) + 0.3 * r);
      out.second.push_back(r);
    }
    return out;
  };
  const auto distinct = arc({20, 50, 80});      // three points, all coordinates distinct
  const auto shared = arc({50, 70, 110, 130});  // two pairs with equal y
  const double a =
      estimate<2>(IsosurfaceBasis::linear, distinct.first, distinct.second, Vec2::Zero()).max_error;
  const double b =
      estimate<2>(IsosurfaceBasis::linear, shared.first, shared.second, Vec2::Zero()).max_error;
  std::printf("arc, linear: distinct coordinates %.1f°, shared y %.1f° (paper 6°, 34°)\n",
              a * 180 / pi, b * 180 / pi);
  EXPECT_LT(a * 180 / pi, 8.0);   // measured 5.3°
  EXPECT_GT(b * 180 / pi, 25.0);  // measured 40–45° depending on the extra point
  const auto eight = arc({10, 30, 50, 70, 90, 110, 130, 150});
  EXPECT_LT(
      estimate<2>(IsosurfaceBasis::quadratic, eight.first, eight.second, Vec2::Zero()).max_error,
      1e-8);
}

TEST(NormalsPaper, CubicCurveWithQuadraticShapeFunctions) {
  // Fig 10: y = c x²(x − 1) + x + 0.5: about 1° for c = 2, about 32° for c = 4 (radius of
  // curvature 0.2, below the cell size).
  for (double c : {2.0, 4.0}) {
    std::vector<Vec2> points, exact;
    for (int k = 0; k < 16; ++k) {  // 16 points across the cell
      const double x = 0.05 + 0.9 * k / 15.0;
      points.emplace_back(x, c * x * x * (x - 1) + x + 0.5);
      exact.emplace_back(-(c * (3 * x * x - 2 * x) + 1), 1.0);
    }
    const double e =
        estimate<2>(IsosurfaceBasis::quadratic, points, exact, Vec2::Zero()).max_error * 180 / pi;
    std::printf("cubic c = %.0f, quadratic: max error %.1f° (paper %s)\n", c, e,
                c == 2 ? "1°" : "32°");
    if (c == 2)
      EXPECT_LT(e, 3.0);  // measured 1.5°
    else
      EXPECT_GT(e, 15.0);  // measured 36°: curvature radius 0.2 is below the cell
  }
}

TEST(NormalsPaper, PlaneAndSphereIn3D) {
  // Fig 5a / 11a: the plane 0.5x + 0.25y − z = 0, exact with 9 points (linear) and 30
  // (quadratic). Fig 5b / 11b: the sphere of radius 0.8: linear with 8 points about 13° max,
  // 3° rms; quadratic with 29 points exact.
  auto plane = [](int n) {
    std::pair<std::vector<Vec3>, std::vector<Vec3>> out;
    for (int k = 0; k < n; ++k) {
      const double x = std::fmod(0.137 + 0.618034 * k, 1.0),
                   y = std::fmod(0.271 + 0.414214 * k, 1.0);
      out.first.emplace_back(x, y, 0.5 * x + 0.25 * y);
      out.second.emplace_back(0.5, 0.25, -1.0);
    }
    return out;
  };
  auto sphere = [](int n) {
    std::pair<std::vector<Vec3>, std::vector<Vec3>> out;
    for (int k = 0; k < n; ++k) {  // spread over the octant inside the unit cube
      const double u = (k + 0.5) / n, a = 0.5 * pi * std::fmod(0.618034 * k + 0.1, 1.0);
      const double z = 0.05 + 0.9 * u, r = std::sqrt(1 - z * z);
      const Vec3 d(r * std::cos(a), r * std::sin(a), z);
      out.first.push_back(0.8 * d);
      out.second.push_back(d);
    }
    return out;
  };
  const auto p9 = plane(9), p30 = plane(30);
  EXPECT_LT(estimate<3>(IsosurfaceBasis::linear, p9.first, p9.second, Vec3::Zero()).max_error,
            1e-8);
  EXPECT_LT(estimate<3>(IsosurfaceBasis::quadratic, p30.first, p30.second, Vec3::Zero()).max_error,
            1e-8);
  const auto s8 = sphere(8), s29 = sphere(29);
  const auto linear = estimate<3>(IsosurfaceBasis::linear, s8.first, s8.second, Vec3::Zero());
  std::printf("sphere, linear, 8 points: max %.1f° rms %.1f° (paper 13°, 3°)\n",
              linear.max_error * 180 / pi, linear.rms_error * 180 / pi);
  EXPECT_LT(linear.max_error * 180 / pi, 25.0);
  EXPECT_LT(estimate<3>(IsosurfaceBasis::quadratic, s29.first, s29.second, Vec3::Zero()).max_error,
            1e-8);
}

}  // namespace
}  // namespace pellicle
