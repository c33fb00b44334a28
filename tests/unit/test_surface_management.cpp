// Point management of Suchde & Kuhnert §3.4–3.5: hole filling on one-ring triangulations
// (with the boundary kept), merging of close points, the second-order MLS interpolation
// that carries every quantity to new and merged points, the curvature-corrected addition of
// eqs 6–9 on a sphere and a torus (the experiment of §3.7.4, Table 1, Figure 11) and the
// same on a curve.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>

#include "pellicle/pointcloud/neighbour_search.hpp"
#include "pellicle/surface/frames.hpp"
#include "pellicle/surface/gfdm.hpp"
#include "pellicle/surface/management.hpp"
#include "pellicle/surface/mls_interpolation.hpp"
#include "pellicle/surface/one_ring.hpp"
#include "pellicle/surface/point_cloud.hpp"
#include "support/test_clouds.hpp"

namespace pellicle {
namespace {

//! Frames as a simulation has them: eq 4, oriented, and (with `refine`) the second-order
//! normals of gfdm.hpp.
template <int D>
void prepare_frames(PointCloud<D>& c, NeighbourSearch<D>& search, bool refine) {
  NeighbourLists nb;
  search.find(c, nb);
  estimate_frames(c, nb, FrameOptions{}, false);
  orient_consistently(c, nb);
  if (refine) {
    SurfaceStencils<D> st;
    build_stencils(c, nb, GfdmOptions{}, st);
    refine_normals(c, nb, st);
  }
}

template <int D>
double closest_pair(const PointCloud<D>& c, double& relative) {
  double closest = 1e300;
  relative = 1e300;
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = i + 1; j < c.size(); ++j) {
      const double d = (c.position[i] - c.position[j]).norm();
      closest = std::min(closest, d);
      relative = std::min(relative, d / std::max(c.smoothing_length[i], c.smoothing_length[j]));
    }
  return closest;
}

// A tilted plane patch: a jittered square lattice whose outer ring lies on the square's
// edges and is flagged as the boundary. Plane coordinates (a, b) along e1, e2 from `origin`.
struct Patch {
  const double tilt = 0.35;
  const Vec3 origin{0.1, 0.2, 0.3};
  const Vec3 e1{1.0, 0.0, 0.0};
  const Vec3 e2{0.0, std::cos(tilt), std::sin(tilt)};
  const Vec3 normal = e1.cross(e2);
  Vec3 at(double a, double b) const { return origin + a * e1 + b * e2; }
  Eigen::Vector2d coordinates(const Vec3& x) const {
    return {(x - origin).dot(e1), (x - origin).dot(e2)};
  }
  // Quadratic fields of the plane coordinates, which the MLS reproduces exactly.
  static double u(const Eigen::Vector2d& p) {
    const double a = p[0], b = p[1];
    return 1 + 2 * a - b + 0.5 * a * a + 3 * a * b - 2 * b * b;
  }
  Vec3 v(const Eigen::Vector2d& p) const {
    return (p[0] * p[1] - 0.3) * e1 + (p[0] * p[0] + p[1]) * e2 + 0.5 * p[1] * p[1] * normal;
  }
  static double h_of(const Eigen::Vector2d& p) { return 0.1 + 0.01 * p[0] + 0.02 * p[0] * p[1]; }

  //! `keep(i, j, a, b)` says which lattice points to keep.
  PointCloud<3> cloud(int n, std::function<bool(int, int, double, double)> keep,
                      bool variable_h = false) const {
    std::mt19937 rng(17);
    const double s = 1.0 / (n - 1);
    std::uniform_real_distribution<double> jitter(-0.15 * s, 0.15 * s);
    PointCloud<3> c;
    c.add_field("u");
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const bool edge_i = i == 0 || i == n - 1, edge_j = j == 0 || j == n - 1;
        double a = -0.5 + i * s, b = -0.5 + j * s;
        const double da = jitter(rng), db = jitter(rng);
        if (!edge_i) a += da;  // boundary points move only along their edge
        if (!edge_j) b += db;
        if (!keep(i, j, a, b)) continue;
        const Eigen::Vector2d p(a, b);
        const std::size_t k = c.add_point(at(a, b), variable_h ? h_of(p) : 0.1, edge_i || edge_j);
        fill(c, k);
      }
    return c;
  }
  void fill(PointCloud<3>& c, std::size_t k) const {
    const Eigen::Vector2d p = coordinates(c.position[k]);
    c.field(0)[k] = u(p);
    c.velocity[k] = v(p);
    c.previous_velocity[k] = 2.0 * v(p);
    c.has_previous_velocity[k] = 1;
  }
  bool on_edge(const Vec3& x) const {
    const Eigen::Vector2d p = coordinates(x);
    return std::abs(std::abs(p[0]) - 0.5) < 1e-12 || std::abs(std::abs(p[1]) - 0.5) < 1e-12;
  }
};

//! Places of the square farther than r_max h from every point (a 0.004 grid of probes).
long holes_in_patch(const Patch& patch, const PointCloud<3>& c, NeighbourSearch<3>& search,
                    double hole) {
  NeighbourLists nb;
  search.find(c, nb);
  std::vector<int> found;
  long holes = 0;
  for (double a = -0.5; a <= 0.5; a += 0.004)
    for (double b = -0.5; b <= 0.5; b += 0.004) {
      search.around(c, patch.at(a, b), hole, found);
      holes += found.empty();
    }
  return holes;
}

//! Triangles of the one-rings that the filling looks for and that remain: globally empty
//! circumsphere, circumcentre inside, not three boundary points, circumradius > r_max h.
long large_triangles(const PointCloud<3>& c, NeighbourSearch<3>& search,
                     const ManagementOptions& o) {
  NeighbourLists nb;
  search.find(c, nb, o.one_ring_radius);
  OneRingSimplex ring[kMaxOneRing];
  std::vector<int> found;
  long large = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const int count = one_ring<3>(c, nb, i, o.one_ring_radius * c.smoothing_length[i], ring);
    for (int t = 0; t < count; ++t) {
      const int a = static_cast<int>(i), b = ring[t].first, d = ring[t].second;
      if (c.boundary[a] && c.boundary[b] && c.boundary[d]) continue;
      const Circumcircle cc = circumcircle(c.position[a], c.position[b], c.position[d]);
      const double h = (c.smoothing_length[a] + c.smoothing_length[b] + c.smoothing_length[d]) / 3;
      if (!(cc.radius > o.r_max * h) || !cc.inside()) continue;
      search.around(c, cc.centre, cc.radius * (1 - 1e-9), found);
      bool empty = true;
      for (int k : found) empty = empty && (k == a || k == b || k == d);
      large += empty;
    }
  }
  return large;
}

// A hole of radius 0.8 h in the interior and a gap of five points in the boundary of a plane
// patch: both are filled, every new point lies in the plane (boundary ones on their edge),
// carries the quadratic fields exactly, and the result has no probe farther than r_max h
// from every point, no one-ring triangle with circumradius above r_max h and no pair closer
// than r_min h.
TEST(SurfaceManagement, FillsAHoleAndABoundaryGapInAPlanePatch) {
  const Patch patch;
  const int n = 26;
  auto c = patch.cloud(n, [](int i, int j, double a, double b) {
    if (j == 0 && i >= 10 && i <= 12) return false;              // the boundary gap
    return std::hypot(a - 0.05, b) >= 0.08 || i == 0 || j == 0;  // the hole
  });
  NeighbourSearch<3> search;
  prepare_frames(c, search, false);
  const ManagementOptions options;
  const double hole = options.r_max * 0.1;
  EXPECT_GT(holes_in_patch(patch, c, search, hole), 100);
  const std::size_t before = c.size();

  const ManagementReport report = manage_points(c, search, options, FrameOptions{});
  std::printf("patch: %zu points, %ld added in %d passes, %ld widened fits\n", before, report.added,
              report.fill_passes, report.widened_fits);
  EXPECT_TRUE(report.filled);
  EXPECT_EQ(report.merged + report.removed, 0);
  ASSERT_EQ(c.size(), before + report.added);
  ASSERT_GT(report.added, 5);  // about as many as the hole took (10)
  EXPECT_EQ(holes_in_patch(patch, c, search, hole), 0);
  EXPECT_EQ(large_triangles(c, search, options), 0);
  double relative = 0;
  closest_pair(c, relative);
  EXPECT_GE(relative, options.r_min);

  long boundary_added = 0;
  for (std::size_t i = before; i < c.size(); ++i) {
    const Eigen::Vector2d p = patch.coordinates(c.position[i]);
    EXPECT_NEAR((c.position[i] - patch.origin).dot(patch.normal), 0.0, 1e-12) << i;
    EXPECT_NEAR(c.field(0)[i], Patch::u(p), 1e-10) << i;
    EXPECT_LT((c.velocity[i] - patch.v(p)).norm(), 1e-10) << i;
    EXPECT_EQ(c.has_previous_velocity[i], 1);
    EXPECT_LT((c.previous_velocity[i] - 2.0 * patch.v(p)).norm(), 1e-10) << i;
    EXPECT_NEAR(c.smoothing_length[i], 0.1, 1e-12);
    EXPECT_GT(std::abs(c.normal(i).dot(patch.normal)), 1.0 - 1e-12);
    EXPECT_GT(c.normal(i).dot(c.normal(0)), 0.0);  // the side of the others (eq 5)
    if (c.boundary[i]) {
      ++boundary_added;
      EXPECT_NEAR(p[1], -0.5, 1e-12) << i;  // on the bottom edge, in the gap
      EXPECT_GT(p[0], -0.5 + 9.0 / (n - 1));
      EXPECT_LT(p[0], -0.5 + 13.0 / (n - 1));
      EXPECT_LT((c.boundary_normal[i] + patch.e2).norm(), 1e-9);  // ν points out
    }
  }
  EXPECT_GE(boundary_added, 1);  // a gap of four spacings (1.6 h) needs one
  for (std::size_t i = 0; i < c.size(); ++i)
    EXPECT_TRUE(!c.boundary[i] || patch.on_edge(c.position[i])) << i;
}

// An interior point on a boundary gap (one added near the boundary before the gap grew into
// a hole) would keep the gap from being filled; it becomes the gap's boundary point instead:
// moved onto the edge, with ν and the values there, and no point is added.
TEST(SurfaceManagement, InteriorPointOnABoundaryGapBecomesItsBoundaryPoint) {
  const Patch patch;
  const int n = 26;  // spacing 0.04 = 0.4 h; without i = 11, 12 the gap is 1.2 h
  auto c = patch.cloud(n, [](int i, int j, double, double) { return j != 0 || i < 11 || i > 12; });
  const double a = -0.5 + 11.5 / (n - 1);
  const std::size_t planted = c.add_point(patch.at(a + 0.003, -0.5 + 0.006), 0.1, false);
  patch.fill(c, planted);
  NeighbourSearch<3> search;
  prepare_frames(c, search, false);
  const std::size_t before = c.size();
  const ManagementReport report = manage_points(c, search, ManagementOptions{}, FrameOptions{});
  EXPECT_EQ(report.promoted, 1);
  EXPECT_EQ(report.added, 0);
  ASSERT_EQ(c.size(), before);
  ASSERT_EQ(c.boundary[planted], 1);
  const Eigen::Vector2d p = patch.coordinates(c.position[planted]);
  EXPECT_NEAR(p[1], -0.5, 1e-12);  // on the edge, halfway along the gap
  EXPECT_NEAR(p[0], a, 0.01);
  EXPECT_NEAR(c.field(0)[planted], Patch::u(p), 1e-10);
  EXPECT_LT((c.boundary_normal[planted] + patch.e2).norm(), 1e-9);
}

// The same hole with its rim flagged as boundary (a hole in the manifold, not in the cloud)
// stays open: no triangle of three boundary points is filled.
TEST(SurfaceManagement, LeavesAHoleInTheManifoldOpen) {
  const Patch patch;
  auto c =
      patch.cloud(23, [](int, int, double a, double b) { return std::hypot(a - 0.05, b) >= 0.08; });
  for (std::size_t i = 0; i < c.size(); ++i)
    if ((patch.coordinates(c.position[i]) - Eigen::Vector2d(0.05, 0.0)).norm() < 0.08 + 0.05)
      c.boundary[i] = 1;
  NeighbourSearch<3> search;
  prepare_frames(c, search, false);
  const ManagementReport report = manage_points(c, search, ManagementOptions{}, FrameOptions{});
  for (std::size_t i = 0; i < c.size(); ++i)
    EXPECT_GE((patch.coordinates(c.position[i]) - Eigen::Vector2d(0.05, 0.0)).norm(), 0.08 - 1e-9);
  EXPECT_EQ(report.added, 0);
}

// Points closer than r_min h: interior pairs merged into one, interior points next to a
// boundary point dropped (the boundary point stays exactly where it was), boundary pairs
// merged on their edge; afterwards no pair is closer than r_min h and every point carries the
// quadratic fields exactly (variable h, interpolated like the rest).
TEST(SurfaceManagement, MergesClosePointsAndKeepsTheBoundary) {
  const Patch patch;
  const int n = 23;
  auto c = patch.cloud(
      n, [](int, int, double, double) { return true; }, true);
  NeighbourSearch<3> search;
  prepare_frames(c, search, false);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> angle(0.0, 2 * std::numbers::pi);
  std::vector<Vec3> kept_boundary;
  const std::size_t lattice = c.size();
  int interior_pairs = 0, boundary_interior = 0, boundary_pairs = 0;
  for (std::size_t k = 0; k < lattice; ++k) {
    const Eigen::Vector2d p = patch.coordinates(c.position[k]);
    const double h = c.smoothing_length[k];
    if (!c.boundary[k] && k % 17 == 0) {  // an interior pair
      const double t = angle(rng);
      const Vec3 x = c.position[k] + 0.1 * h * (std::cos(t) * patch.e1 + std::sin(t) * patch.e2);
      patch.fill(c, c.add_point(x, Patch::h_of(patch.coordinates(x)), false));
      ++interior_pairs;
    } else if (c.boundary[k] && std::abs(p[0]) < 0.45 && p[1] < -0.49 && k % 3 == 0) {
      // an interior point just inside a boundary point of the bottom edge
      const Vec3 x = c.position[k] + 0.12 * h * patch.e2 + 0.05 * h * patch.e1;
      patch.fill(c, c.add_point(x, Patch::h_of(patch.coordinates(x)), false));
      kept_boundary.push_back(c.position[k]);
      ++boundary_interior;
    } else if (c.boundary[k] && std::abs(p[1]) < 0.4 && p[0] > 0.49 && k % 4 == 0) {
      // a second boundary point on the right edge
      const Vec3 x = c.position[k] + 0.15 * h * patch.e2;
      patch.fill(c, c.add_point(x, Patch::h_of(patch.coordinates(x)), true));
      ++boundary_pairs;
    }
  }
  ASSERT_GT(interior_pairs, 10);
  ASSERT_GT(boundary_interior, 3);
  ASSERT_GT(boundary_pairs, 2);
  prepare_frames(c, search, false);
  const ManagementOptions options;
  const ManagementReport report = manage_points(c, search, options, FrameOptions{});
  std::printf(
      "merging: %d interior pairs, %d boundary-interior, %d boundary pairs -> merged %ld,"
      " removed %ld, added %ld\n",
      interior_pairs, boundary_interior, boundary_pairs, report.merged, report.removed,
      report.added);
  EXPECT_EQ(report.merged, interior_pairs + boundary_pairs);
  EXPECT_EQ(report.removed, boundary_interior);
  double relative = 0;
  closest_pair(c, relative);
  EXPECT_GE(relative, options.r_min);
  for (const Vec3& x : kept_boundary) {
    bool found = false;
    for (std::size_t i = 0; i < c.size(); ++i)
      found = found || (c.position[i] == x && c.boundary[i]);
    EXPECT_TRUE(found);
  }
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Eigen::Vector2d p = patch.coordinates(c.position[i]);
    EXPECT_NEAR((c.position[i] - patch.origin).dot(patch.normal), 0.0, 1e-12);
    EXPECT_TRUE(!c.boundary[i] || patch.on_edge(c.position[i])) << i;
    EXPECT_NEAR(c.field(0)[i], Patch::u(p), 1e-10) << i;
    EXPECT_LT((c.velocity[i] - patch.v(p)).norm(), 1e-10) << i;
    EXPECT_NEAR(c.smoothing_length[i], Patch::h_of(p), 1e-10) << i;
  }
}

// The interpolation reproduces quadratics of the tangent coordinates (b = e_0 with the
// constraints of eq 18), whatever the in-plane rotation of the target's frame.
TEST(SurfaceManagement, MlsInterpolationExactForQuadraticsInThePlane) {
  const double tilt = 0.4;
  auto c = test::random_patch(1500, 0.2, tilt);
  NeighbourSearch<3> search;
  prepare_frames(c, search, false);
  const Vec3 e1(1, 0, 0), e2(0, std::cos(tilt), std::sin(tilt));
  const int f = c.add_field("u");
  auto u = [&](const Vec3& x) {
    const double a = x.dot(e1), b = x.dot(e2);
    return -0.5 + a - 2 * b + 1.5 * a * a - a * b + 0.25 * b * b;
  };
  for (std::size_t i = 0; i < c.size(); ++i) {
    c.field(f)[i] = u(c.position[i]);
    c.velocity[i] = Vec3(u(c.position[i]), c.position[i].x() * c.position[i].y(), 1.0);
  }
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> place(-0.7, 0.7), turn(0.0, 2 * std::numbers::pi);
  std::vector<MlsTarget<3>> targets;
  for (int q = 0; q < 300; ++q) {
    MlsTarget<3> t;
    t.position = place(rng) * e1 + place(rng) * e2;
    const double r = turn(rng);
    t.frame = c.frame[0];
    t.frame.col(0) = std::cos(r) * c.frame[0].col(0) + std::sin(r) * c.frame[0].col(1);
    set_normal<3>(t.frame, c.normal(0));
    t.h = 0.2;
    targets.push_back(t);
  }
  CarriedValues<3> values;
  EXPECT_EQ(interpolate_carried(c, search, targets, 2.0, values), 0);
  double worst = 0.0;
  for (std::size_t q = 0; q < targets.size(); ++q) {
    const Vec3& x = targets[q].position;
    worst = std::max(worst, std::abs(values.fields[f][q] - u(x)));
    worst = std::max(worst, (values.velocity[q] - Vec3(u(x), x.x() * x.y(), 1.0)).norm());
    worst = std::max(worst, std::abs(values.smoothing_length[q] - 0.2));
  }
  std::printf("MLS on the plane: largest error %.2e\n", worst);
  EXPECT_LT(worst, 1e-10);
}

// On the unit sphere the tangent-plane fit is second order: the largest error of
// u = e^x sin(2y) + z at random places falls as h³ or faster (measured 1.1e-2, 1.3e-3,
// 9.7e-5 for h = 0.4, 0.2, 0.1: orders 3.1, 3.7).
TEST(SurfaceManagement, MlsInterpolationSecondOrderOnTheSphere) {
  auto u = [](const Vec3& x) { return std::exp(x.x()) * std::sin(2 * x.y()) + x.z(); };
  std::vector<double> errors;
  for (double h : {0.4, 0.2, 0.1}) {
    auto c = test::jittered_sphere(1.0, h);
    NeighbourSearch<3> search;
    prepare_frames(c, search, true);
    const int f = c.add_field("u");
    for (std::size_t i = 0; i < c.size(); ++i) c.field(f)[i] = u(c.position[i]);
    std::mt19937 rng(2);
    std::normal_distribution<double> g;
    std::vector<MlsTarget<3>> targets;
    for (int q = 0; q < 400; ++q) {
      MlsTarget<3> t;
      t.position = Vec3(g(rng), g(rng), g(rng)).normalized();
      t.frame = Mat3::Identity();
      set_normal<3>(t.frame, t.position);
      t.h = h;
      targets.push_back(t);
    }
    CarriedValues<3> values;
    interpolate_carried(c, search, targets, 2.0, values);
    double worst = 0.0;
    for (std::size_t q = 0; q < targets.size(); ++q)
      worst = std::max(worst, std::abs(values.fields[f][q] - u(targets[q].position)));
    errors.push_back(worst);
  }
  for (std::size_t k = 0; k < errors.size(); ++k) {
    std::printf("MLS on the sphere, h %.2f: largest error %.2e", 0.4 / (1 << k), errors[k]);
    if (k > 0) std::printf(" (order %.2f)", std::log2(errors[k - 1] / errors[k]));
    std::printf("\n");
  }
  for (std::size_t k = 1; k < errors.size(); ++k)
    EXPECT_GT(std::log2(errors[k - 1] / errors[k]), 2.5);
  EXPECT_LT(errors.back(), 2e-4);
}

// §3.7.4, Table 1 and Figure 11: a cloud spaced for h0 (about 3.4 points per h0², what the
// filling itself leaves: 11 neighbours within h), h halved, the filling refines it (about
// four times the points, as in the paper); the error of the added points is the mean of
// |‖x‖² − 1| (eq 13) on the unit sphere, of |(c − √(x² + y²))² + z² − a²| (eq 15) on the
// torus c = 3, a = 1. Normals: eq 4 refined to second order (gfdm.hpp).
struct AdditionErrors {
  std::vector<long> before, after;
  std::vector<double> plain, paper, midway;  // no correction, eq 9, the midway rule
  std::vector<double> paper_signed, plain_signed;
};

AdditionErrors addition_errors(const std::vector<double>& h0s,
                               std::function<PointCloud<3>(double)> make,
                               std::function<double(const Vec3&)> error,
                               std::function<Vec3(const Vec3&)> exact_normal) {
  AdditionErrors out;
  for (const double h0 : h0s) {
    for (int rule = 0; rule < 3; ++rule) {
      auto c = make(h0);
      NeighbourSearch<3> search;
      prepare_frames(c, search, true);
      const std::size_t before = c.size();
      for (double& h : c.smoothing_length) h = 0.5 * h0;
      ManagementOptions o;
      o.curvature_correction = rule > 0;
      o.curvature_rule = rule == 2 ? CurvatureRule::midway : CurvatureRule::tangent_planes;
      const ManagementReport r = manage_points(c, search, o, FrameOptions{});
      EXPECT_TRUE(r.filled);
      EXPECT_EQ(r.merged + r.removed, 0);
      double e = 0.0, signed_e = 0.0;
      for (std::size_t i = c.size() - r.added; i < c.size(); ++i) {
        e += std::abs(error(c.position[i]));
        signed_e += error(c.position[i]);
        EXPECT_GT(c.normal(i).dot(exact_normal(c.position[i])), 0.99);
      }
      e /= r.added;
      signed_e /= r.added;
      // No pair closer than r_min h: only the point itself within r_min h.
      NeighbourLists close;
      search.find(c, close, o.r_min);
      long close_pairs = 0;
      for (std::size_t i = 0; i < c.size(); ++i) close_pairs += close.count(i) - 1;
      EXPECT_EQ(close_pairs, 0);
      if (rule == 0) {
        out.before.push_back(static_cast<long>(before));
        out.after.push_back(static_cast<long>(c.size()));
        out.plain.push_back(e);
        out.plain_signed.push_back(signed_e);
      } else if (rule == 1) {
        out.paper.push_back(e);
        out.paper_signed.push_back(signed_e);
      } else {
        out.midway.push_back(e);
      }
    }
  }
  return out;
}

void print_and_check(const char* name, const std::vector<double>& h0s, const AdditionErrors& e) {
  std::printf(
      "%s: h0, points before -> after, error of added points: circumcentre | eq 9 | "
      "midway (orders)\n",
      name);
  for (std::size_t k = 0; k < h0s.size(); ++k) {
    std::printf("  %.3f %7ld -> %7ld  %.3e | %.3e | %.3e", h0s[k], e.before[k], e.after[k],
                e.plain[k], e.paper[k], e.midway[k]);
    if (k > 0)
      std::printf("  (%.2f | %.2f | %.2f)", std::log2(e.plain[k - 1] / e.plain[k]),
                  std::log2(e.paper[k - 1] / e.paper[k]), std::log2(e.midway[k - 1] / e.midway[k]));
    std::printf("\n");
  }
  for (std::size_t k = 0; k < h0s.size(); ++k) {
    EXPECT_GT(static_cast<double>(e.after[k]) / e.before[k], 3.5);  // h halved: ~4x points
    // The circumcentre lies inside (the chord's sagitta), eq 9 as far outside.
    EXPECT_LT(e.plain_signed[k], 0.0);
    EXPECT_GT(e.paper_signed[k], 0.0);
    EXPECT_GT(e.paper[k] / e.plain[k], 0.8);
    EXPECT_LT(e.paper[k] / e.plain[k], 1.25);
    EXPECT_LT(e.midway[k], 0.05 * e.plain[k]);
  }
  for (std::size_t k = 1; k < h0s.size(); ++k) {
    EXPECT_NEAR(std::log2(e.plain[k - 1] / e.plain[k]), 2.0, 0.25);
    EXPECT_NEAR(std::log2(e.paper[k - 1] / e.paper[k]), 2.0, 0.25);
    EXPECT_GT(std::log2(e.midway[k - 1] / e.midway[k]), 3.0);
  }
}

// Measured, mean error of the added points (order against the previous row):
//   h0     points          circumcentre      eq 9              midway
//   0.40    267 ->  1120   2.21e-2           2.18e-2           9.38e-5
//   0.20   1068 ->  4479   5.52e-3 (2.00)    5.35e-3 (2.02)    5.75e-6 (4.03)
//   0.10   4272 -> 18772   1.40e-3 (1.97)    1.36e-3 (1.98)    3.76e-7 (3.93)
//   0.05  17090 -> 71241   3.45e-4 (2.02)    3.33e-4 (2.03)    2.25e-8 (4.07)
// The paper's Figure 11 has eq 9 halving the error and both converging faster than h²;
// neither is reproduced. Eq 8 puts the point where the tangent planes of the three points
// meet, as far outside the sphere as the circumcentre lies inside it (the signed errors
// have opposite signs, the sizes agree to 4 %); the midway rule lands on the sphere to
// leading order (docs/theory/surface-management.md). With the eq 4 normals alone (not
// refined) the midway errors are 1.3e-3, 3.0e-4, 6.5e-5, 1.9e-5 (order 2) and the others
// unchanged.
TEST(SurfaceManagement, CurvatureCorrectedAdditionOnTheSphere) {
  const std::vector<double> h0s = {0.4, 0.2, 0.1, 0.05};
  const AdditionErrors e = addition_errors(
      h0s, [](double h0) { return test::jittered_sphere(1.0, h0, 3.4); },
      [](const Vec3& x) { return x.squaredNorm() - 1.0; },
      [](const Vec3& x) { return Vec3(x.normalized()); });
  print_and_check("sphere", h0s, e);
}

// The torus c = 3, a = 1, error of eq 15. Measured:
//   h0     points          circumcentre      eq 9              midway
//   0.80    605 ->  2656   5.10e-2           4.90e-2           7.51e-4
//   0.40   2518 -> 10486   1.20e-2 (2.09)    1.13e-2 (2.11)    6.11e-5 (3.62)
//   0.20  10074 -> 42239   3.01e-3 (1.99)    2.82e-3 (2.00)    6.37e-6 (3.26)
// (h0 = 0.1, left out of ctest for time: 40319 -> 168344, 7.48e-4, 7.01e-4, 7.51e-7.)
TEST(SurfaceManagement, CurvatureCorrectedAdditionOnTheTorus) {
  const double c = 3.0, a = 1.0;
  const std::vector<double> h0s = {0.8, 0.4, 0.2};
  const AdditionErrors e = addition_errors(
      h0s, [&](double h0) { return test::jittered_torus(c, a, h0, 3.4); },
      [&](const Vec3& x) {
        const double r = std::hypot(x.x(), x.y());
        return (c - r) * (c - r) + x.z() * x.z() - a * a;
      },
      [&](const Vec3& x) { return test::torus_normal(x, c); });
  print_and_check("torus", h0s, e);
}

// A curve: a jittered circle whose h drops from three spacings to one. Segments longer than
// 2 r_max h get a point halfway (a 'triangle' on a curve is a segment between neighbours
// along it); afterwards no segment is longer than 2 r_max h and no two points are closer
// than r_min h. The radial error |‖x‖² − 1| of the new points, mean over them, and the
// largest error of the interpolated u = cos 2θ (measured, n = 64, 128, 256):
//   midpoint 1.3e-3, 3.2e-4, 8.0e-5 (order 2.0), eq 9 the same size outside, midway
//   1.0e-6, 6.4e-8, 4.0e-9 (order 4); u 1.3e-4, 1.6e-5, 2.0e-6 (order 3).
TEST(SurfaceManagement, CurveRefinementOnACircle) {
  std::vector<double> errors[3], field_errors;
  for (int n : {64, 128, 256}) {
    const double s = 2 * std::numbers::pi / n;
    for (int rule = 0; rule < 3; ++rule) {
      auto c = test::jittered_circle(1.0, n, 3 * s);
      const int f = c.add_field("u");
      for (std::size_t i = 0; i < c.size(); ++i) {
        const Vec2 x = c.position[i];
        c.field(f)[i] = std::cos(2 * std::atan2(x.y(), x.x()));
        c.velocity[i] = Vec2(-x.y(), x.x());
      }
      NeighbourSearch<2> search;
      prepare_frames(c, search, true);
      for (double& h : c.smoothing_length) h = s;
      ManagementOptions o;
      o.curvature_correction = rule > 0;
      o.curvature_rule = rule == 2 ? CurvatureRule::midway : CurvatureRule::tangent_planes;
      const ManagementReport r = manage_points(c, search, o, FrameOptions{});
      EXPECT_TRUE(r.filled);
      ASSERT_GT(r.added, n / 4);
      double e = 0.0, worst_u = 0.0;
      for (std::size_t i = c.size() - r.added; i < c.size(); ++i) {
        const Vec2 x = c.position[i];
        e += std::abs(x.squaredNorm() - 1.0);
        worst_u =
            std::max(worst_u, std::abs(c.field(f)[i] - std::cos(2 * std::atan2(x.y(), x.x()))));
        EXPECT_LT((c.velocity[i] - Vec2(-x.y(), x.x())).norm(), 0.25 * s * s) << i;
        EXPECT_GT(c.normal(i).dot(x), 0.99);
      }
      errors[rule].push_back(e / r.added);
      if (rule == 2) field_errors.push_back(worst_u);
      std::vector<double> angles;
      for (const Vec2& x : c.position) angles.push_back(std::atan2(x.y(), x.x()));
      std::sort(angles.begin(), angles.end());
      double longest = 2 * std::numbers::pi - angles.back() + angles.front(), shortest = longest;
      for (std::size_t k = 1; k < angles.size(); ++k) {
        longest = std::max(longest, angles[k] - angles[k - 1]);
        shortest = std::min(shortest, angles[k] - angles[k - 1]);
      }
      EXPECT_LE(2 * std::sin(longest / 2), 2 * o.r_max * s);
      EXPECT_GE(2 * std::sin(shortest / 2), o.r_min * s);
    }
  }
  for (std::size_t k = 0; k < 3; ++k) {
    std::printf("circle n %d: midpoint %.2e, eq 9 %.2e, midway %.2e; u %.2e\n", 64 << k,
                errors[0][k], errors[1][k], errors[2][k], field_errors[k]);
  }
  for (std::size_t k = 1; k < 3; ++k) {
    EXPECT_NEAR(std::log2(errors[0][k - 1] / errors[0][k]), 2.0, 0.3);
    EXPECT_GT(std::log2(errors[2][k - 1] / errors[2][k]), 3.0);
    EXPECT_GT(std::log2(field_errors[k - 1] / field_errors[k]), 2.5);
  }
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(errors[1][k] / errors[0][k], 1.0, 0.25);
    EXPECT_LT(errors[2][k], 0.01 * errors[0][k]);
  }
}

// An open arc (ends flagged as boundary) with points crowded onto it: close pairs merge,
// an interior point next to an end goes and the end stays, and the gap between the two ends
// is never bridged (no segment between two boundary points).
TEST(SurfaceManagement, CurveMergingKeepsTheEndsAndTheirGap) {
  const int n = 120;
  const double gap = 0.3, h = 0.15;  // the ends 2 sin(0.15) ≈ 0.3 apart > 2 r_max h
  PointCloud<2> c;
  const int f = c.add_field("u");
  auto put = [&](double angle, bool end) {
    const std::size_t i = c.add_point(Vec2(std::cos(angle), std::sin(angle)), h, end);
    c.field(f)[i] = std::sin(angle);
  };
  const double span = 2 * std::numbers::pi - gap;
  for (int k = 0; k <= n; ++k) put(gap / 2 + span * k / n, k == 0 || k == n);
  const double step = span / n;  // 0.05 = h/3
  for (int k = 5; k < n; k += 10) put(gap / 2 + span * k / n + 0.1 * step, false);
  put(gap / 2 + 0.2 * step, false);          // next to the first end
  put(gap / 2 + span - 0.25 * step, false);  // and the last
  const Vec2 first = c.position[0], last = c.position[n];
  NeighbourSearch<2> search;
  prepare_frames(c, search, false);
  const ManagementOptions o;
  const ManagementReport r = manage_points(c, search, o, FrameOptions{});
  std::printf("arc: merged %ld, removed %ld, added %ld\n", r.merged, r.removed, r.added);
  EXPECT_EQ(r.removed, 2);
  EXPECT_GE(r.merged, 12);
  double relative = 0;
  closest_pair(c, relative);
  EXPECT_GE(relative, o.r_min);
  int ends = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Vec2 x = c.position[i];
    double angle = std::atan2(x.y(), x.x());
    if (angle < 0) angle += 2 * std::numbers::pi;
    EXPECT_GE(angle, gap / 2 - 1e-12);  // nothing in the gap
    EXPECT_LE(angle, 2 * std::numbers::pi - gap / 2 + 1e-12);
    EXPECT_NEAR(x.norm(), 1.0, 1e-3);
    EXPECT_NEAR(c.field(f)[i], x.y(), 1e-4);
    if (c.boundary[i]) {
      ++ends;
      EXPECT_TRUE(x == first || x == last);
    }
  }
  EXPECT_EQ(ends, 2);
}

// A cloud the management has already been through is left alone. The time of both calls is
// printed (measured on one thread of a shared machine: 0.55 s to refine 10 074 points to
// 42 354 with h halved, 0.15 s for the second call on 42 354 points that finds nothing).
TEST(SurfaceManagement, ManagedCloudIsLeftAlone) {
  auto c = test::jittered_torus(3.0, 1.0, 0.2, 3.4);
  NeighbourSearch<3> search;
  prepare_frames(c, search, true);
  for (double& h : c.smoothing_length) h = 0.1;
  const ManagementOptions o;
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const ManagementReport first = manage_points(c, search, o, FrameOptions{});
  const auto t1 = Clock::now();
  EXPECT_GT(first.added, 20000);
  prepare_frames(c, search, true);
  const auto t2 = Clock::now();
  const ManagementReport second = manage_points(c, search, o, FrameOptions{});
  const auto t3 = Clock::now();
  std::printf("torus: %ld points refined to %zu in %.0f ms; again: %s in %.0f ms\n",
              static_cast<long>(c.size() - first.added), c.size(),
              std::chrono::duration<double, std::milli>(t1 - t0).count(),
              second.changed() ? "changed" : "unchanged",
              std::chrono::duration<double, std::milli>(t3 - t2).count());
  EXPECT_FALSE(second.changed());
  EXPECT_TRUE(second.filled);
}

}  // namespace
}  // namespace pellicle
