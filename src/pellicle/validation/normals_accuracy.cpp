// Normals of whole closed curves (circle, ellipse, dog-bone) and surfaces (sphere, torus)
// sampled at spacing ds on a grid of cell h (unit cell, origin off the shapes' symmetry), by
// every estimator: maximum and rms angle errors against the exact normals, tabulated against
// ds/h and curvature × h (Sulsky & York 2000 §4–8; thesis ch. 7).
#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "pellicle/geometry/curve.hpp"
#include "pellicle/geometry/surface_mesh.hpp"
#include "pellicle/normals/frame_estimator.hpp"
#include "pellicle/validation/problem.hpp"

namespace pellicle::validation {
namespace {

constexpr double pi = std::numbers::pi;

template <int D>
struct Shape {
  std::string name;
  double curvature;  //!< largest curvature (2D) or largest principal curvature (3D)
  std::vector<Vec<D>> points, exact;
  MembraneConnectivity connectivity;
};

struct Errors {
  double max = 0.0, rms = 0.0;  // degrees
};

template <int D>
Errors measure(const FrameEstimatorChoice<D>& method, const Shape<D>& s) {
  FrameSetup<D> setup;
  setup.cell = 1.0;
  setup.grid_origin = Vec<D>::Constant(0.137);
  setup.connectivity = s.connectivity;
  auto estimator = method.make(setup);
  const long n = static_cast<long>(s.points.size());
  std::vector<Vec<D>> normal(n, Vec<D>::Zero()), tangent(n, Vec<D>::Zero());
  estimator->estimate(s.points, 0, n, normal, tangent);
  Errors e;
  double sum = 0.0;
  for (long i = 0; i < n; ++i) {
    const Vec<D> u = s.exact[i].normalized();
    const double angle =
        std::atan2((normal[i] - normal[i].dot(u) * u).norm(), std::abs(normal[i].dot(u)));
    e.max = std::max(e.max, angle);
    sum += angle * angle;
  }
  e.rms = std::sqrt(sum / n) * 180 / pi;
  e.max *= 180 / pi;
  return e;
}

//! A closed parametric curve x(θ), θ ∈ [0, 2π), sampled at spacing ds; normals from x'(θ).
Shape<2> closed_curve(const std::string& name, double curvature,
                      const std::function<Vec2(double)>& x, double ds) {
  Shape<2> s{name, curvature, {}, {}, {}};
  const SampledCurve c = sample_curve([&](double u) { return x(2 * pi * u); }, true, {ds, 0});
  s.points = c.points;
  s.connectivity.closed_curve = true;
  for (const auto& p : c.points) {  // exact normal: perpendicular to x'(θ) at the nearest θ
    double best = 0.0, distance = 1e300;
    for (int k = 0; k < 20000; ++k) {
      const double t = 2 * pi * k / 20000;
      const double d = (x(t) - p).squaredNorm();
      if (d < distance) distance = d, best = t;
    }
    for (int it = 0; it < 30; ++it) {  // refine by Newton on (x(t) − p)·x'(t) = 0
      const double e = 1e-6;
      const Vec2 d1 = (x(best + e) - x(best - e)) / (2 * e),
                 d2 = (x(best + e) - 2 * x(best) + x(best - e)) / (e * e);
      const double f = (x(best) - p).dot(d1), df = d1.squaredNorm() + (x(best) - p).dot(d2);
      best -= f / df;
    }
    const Vec2 t = (x(best + 1e-6) - x(best - 1e-6)).normalized();
    s.exact.emplace_back(-t.y(), t.x());
  }
  return s;
}

Shape<3> surface(const std::string& name, double curvature, const SurfaceMesh& m,
                 const std::function<Vec3(const Vec3&)>& exact_normal) {
  Shape<3> s{name, curvature, m.vertices, {}, {}};
  s.connectivity.triangles = m.triangles;
  for (const auto& v : m.vertices) s.exact.push_back(exact_normal(v));
  return s;
}

}  // namespace

Outcome normals_accuracy(Resolution resolution) {
  Outcome out;
  const Vec2 c2(10.0, 10.0);
  std::vector<double> spacings{0.25, 0.125};
  if (resolution == Resolution::full) spacings.push_back(0.0625);
  std::vector<Shape<2>> curves;
  for (double ds : spacings) {
    for (double r : {8.0, 4.0, 2.0})
      curves.push_back(closed_curve(
          "circle R=" + std::to_string(int(r)), 1 / r,
          [&](double t) { return Vec2(c2 + r * Vec2(std::cos(t), std::sin(t))); }, ds));
    curves.push_back(closed_curve(
        "ellipse 6×3", 6.0 / 9.0,
        [&](double t) { return Vec2(c2 + Vec2(6 * std::cos(t), 3 * std::sin(t))); }, ds));
    // Dog-bone (cf. the paper's Fig 14): r(θ) = 4 + 2.4 cos 2θ, a waist pinched to 1.6.
    curves.push_back(closed_curve(
        "dog-bone", 1.0,
        [&](double t) {
          const double r = 4.0 + 2.4 * std::cos(2 * t);
          return Vec2(c2 + r * Vec2(std::cos(t), std::sin(t)));
        },
        ds));
  }
  std::vector<Shape<3>> surfaces;
  const Vec3 c3 = Vec3::Constant(10.0);
  for (double ds : {0.5, 0.25}) {
    for (double r : {4.0, 2.0})
      surfaces.push_back(surface("sphere R=" + std::to_string(int(r)), 1 / r,
                                 make_ellipsoid(c3, Vec3::Constant(r), ds),
                                 [&](const Vec3& x) { return Vec3(x - c3); }));
    surfaces.push_back(surface("torus 4/1.5", 1 / 1.5, make_torus(c3, Vec3::UnitZ(), 4.0, 1.5, ds),
                               [&](const Vec3& x) {
                                 const Vec3 d = x - c3;
                                 const Vec3 ring = 4.0 * Vec3(d.x(), d.y(), 0).normalized();
                                 return Vec3(d - ring);
                               }));
  }
  // The table: one row per shape and spacing, the rms (max) error of every estimator.
  std::string table =
      "Errors in degrees, rms (max), unit cell; κh = largest curvature × cell.\n\n| shape | ds/h | "
      "κh |";
  for (const auto& m : frame_estimators<2>()) table += " " + m.name + " |";
  table += "\n|---|---|---|";
  for (std::size_t k = 0; k < frame_estimators<2>().size(); ++k) table += "---|";
  table += "\n";
  Series series{
      "normals_rms", "Circles, ds/h = 0.25: rms error (degrees) against κh", {"curvature x h"}, {}};
  for (const auto& m : frame_estimators<2>()) series.columns.push_back(m.name);
  char cell[96];
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const auto& s = curves[i];
    const double ds = spacings[i / 5];
    std::snprintf(cell, sizeof cell, "| %s | %g | %.3g |", s.name.c_str(), ds, s.curvature);
    table += cell;
    std::vector<double> row{s.curvature};
    for (const auto& m : frame_estimators<2>()) {
      const Errors e = measure<2>(m, s);
      std::snprintf(cell, sizeof cell, " %.2g (%.2g) |", e.rms, e.max);
      table += cell;
      row.push_back(e.rms);
      if (m.name == "isosurface-hybrid" && s.name.rfind("circle", 0) == 0 && ds <= 0.125) {
        std::snprintf(cell, sizeof cell, "hybrid, %s, ds/h %g: rms error", s.name.c_str(), ds);
        out.checks.push_back({cell, e.rms, 0.0, 0.0, 1.0, "deg"});
      }
      if (m.name == "connectivity") {
        std::snprintf(cell, sizeof cell, "connectivity, %s, ds/h %g: rms error", s.name.c_str(),
                      ds);
        out.checks.push_back({cell, e.rms, 0.0, 0.0, 1.0, "deg"});
      }
    }
    table += "\n";
    if (ds == spacings.front() && s.name.rfind("circle", 0) == 0) series.rows.push_back(row);
  }
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const auto& s = surfaces[i];
    const double ds = i < 3 ? 0.5 : 0.25;
    std::snprintf(cell, sizeof cell, "| %s | %g | %.3g |", s.name.c_str(), ds, s.curvature);
    table += cell;
    for (const auto& m : frame_estimators<3>()) {
      const Errors e = measure<3>(m, s);
      std::snprintf(cell, sizeof cell, " %.2g (%.2g) |", e.rms, e.max);
      table += cell;
      if ((m.name == "connectivity" || m.name == "pca") && ds <= 0.25) {
        std::snprintf(cell, sizeof cell, "%s, %s, ds/h %g: rms error", m.name.c_str(),
                      s.name.c_str(), ds);
        out.checks.push_back({cell, e.rms, 0.0, 0.0, 1.0, "deg"});
      }
      // The paper's one 3D accuracy figure: linear isosurface fits of points on a sphere of
      // radius 0.8 cells, rms 3° (max 13°; Sulsky & York 2000, Fig. 5(b)). The hybrid's fits
      // over whole surfaces must be no worse.
      if (m.name == "isosurface-hybrid" && s.name.rfind("sphere R=4", 0) == 0 && ds <= 0.25) {
        std::snprintf(cell, sizeof cell, "hybrid, %s, ds/h %g: rms error", s.name.c_str(), ds);
        out.checks.push_back({cell, e.rms, 0.0, 0.0, 3.0, "deg"});
      }
    }
    table += "\n";
  }
  std::sort(series.rows.begin(), series.rows.end());
  out.table = table;
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
