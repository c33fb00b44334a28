#pragma once
// Small irregular clouds for tests of the surface operators: jittered Fibonacci spheres,
// jittered tori, random plane patches and jittered circles, with their smoothing lengths.
#include <cmath>
#include <numbers>
#include <random>

#include "pellicle/surface/point_cloud.hpp"

namespace pellicle::test {

//! About `points_per_h2` points per h² of area on a sphere of radius r, jittered by a fifth
//! of the spacing so that the cloud is irregular.
inline PointCloud<3> jittered_sphere(double radius, double h, double points_per_h2 = 6.0,
                                     unsigned seed = 7) {
  const double area = 4 * std::numbers::pi * radius * radius;
  const int n = static_cast<int>(area * points_per_h2 / (h * h));
  const double spacing = std::sqrt(area / n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.2 * spacing, 0.2 * spacing);
  PointCloud<3> c;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / n, r = std::sqrt(1.0 - z * z);
    Vec3 x(r * std::cos(golden * k), r * std::sin(golden * k), z);
    x = radius * x + Vec3(u(rng), u(rng), u(rng));
    c.add_point(radius * x.normalized(), h, false);
  }
  return c;
}

//! Random points in the square [-1, 1]² of the plane z = 0 (tilted by `tilt` about x).
inline PointCloud<3> random_patch(int n, double h, double tilt = 0.0, unsigned seed = 3) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PointCloud<3> c;
  for (int k = 0; k < n; ++k) {
    const double a = u(rng), b = u(rng);
    c.add_point(Vec3(a, b * std::cos(tilt), b * std::sin(tilt)), h, false);
  }
  return c;
}

//! The closest point of the torus to x (x off the z axis).
inline Vec3 on_torus(const Vec3& x, double c, double a) {
  const Vec3 centre = c * Vec3(x.x(), x.y(), 0.0).normalized();
  return centre + a * (x - centre).normalized();
}

//! The outward normal of the torus at a point near it.
inline Vec3 torus_normal(const Vec3& x, double c) {
  return (x - c * Vec3(x.x(), x.y(), 0.0).normalized()).normalized();
}

//! About `points_per_h2` points per h² of area on the torus (c − √(x² + y²))² + z² = a²
//! (tube radius a about the circle of radius c in the xy-plane): rings around the tube
//! spaced evenly in arc length, each ring's points spaced evenly around the axis with a
//! random phase, then moved by up to a fifth of the spacing in the tangent plane and put
//! back on the torus (closest point).
inline PointCloud<3> jittered_torus(double c, double a, double h, double points_per_h2 = 6.0,
                                    unsigned seed = 11) {
  const double spacing = h / std::sqrt(points_per_h2);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.2 * spacing, 0.2 * spacing), phase(0.0, 1.0);
  PointCloud<3> cloud;
  const int rings = static_cast<int>(std::round(2 * std::numbers::pi * a / spacing));
  for (int r = 0; r < rings; ++r) {
    const double theta = 2 * std::numbers::pi * r / rings;  // around the tube
    const double radius = c + a * std::cos(theta);
    const int n = static_cast<int>(std::round(2 * std::numbers::pi * radius / spacing));
    const double offset = phase(rng);
    for (int k = 0; k < n; ++k) {
      const double phi = 2 * std::numbers::pi * (k + offset) / n;  // around the axis
      const Vec3 axis(std::cos(phi), std::sin(phi), 0.0);
      Vec3 x = radius * axis + Vec3(0, 0, a * std::sin(theta));
      x += Vec3(u(rng), u(rng), u(rng));
      cloud.add_point(on_torus(x, c, a), h, false);
    }
  }
  return cloud;
}

//! n points on a circle of radius r, angles jittered by a fifth of the spacing.
inline PointCloud<2> jittered_circle(double radius, int n, double h, unsigned seed = 5) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  PointCloud<2> c;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * (k + u(rng)) / n;
    c.add_point(Vec2(radius * std::cos(a), radius * std::sin(a)), h, false);
  }
  return c;
}

}  // namespace pellicle::test
