// Surface shapes and their point clouds (Suchde & Kuhnert §2): for every shape, no two
// points closer than the spacing, no hole much wider, every point on the shape with its exact
// normal, boundary points exactly on the cuts and rims, reproducible from the seed; the
// paper's point counts on the unit sphere (Tables 2 and 4); rejected input names its key.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>

#include "pellicle/geometry/poisson_sampling.hpp"
#include "pellicle/geometry/surface_mesh.hpp"
#include "pellicle/geometry/surface_shape.hpp"
#include "pellicle/geometry/surface_shapes.hpp"
#include "pellicle/io/toml_parameters.hpp"

namespace pellicle {
namespace {

constexpr double pi = std::numbers::pi;

template <int D>
using Implicit = std::function<double(const Vec<D>&)>;

template <int D>
double min_distance(const std::vector<Vec<D>>& x) {
  double best = 1e300;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j) best = std::min(best, (x[i] - x[j]).norm());
  return best;
}

//! Largest distance from a probe (a point of the shape) to its nearest sample.
template <int D>
double largest_hole(const std::vector<Vec<D>>& samples, const std::vector<Vec<D>>& probes) {
  double worst = 0.0;
  for (const auto& p : probes) {
    double nearest = 1e300;
    for (const auto& x : samples) nearest = std::min(nearest, (x - p).squaredNorm());
    worst = std::max(worst, std::sqrt(nearest));
  }
  return worst;
}

//! ∇F/|∇F| by central differences.
template <int D>
Vec<D> implicit_normal(const Implicit<D>& f, const Vec<D>& x) {
  const double step = 1e-6;
  Vec<D> g;
  for (int d = 0; d < D; ++d) {
    const Vec<D> e = step * Vec<D>::Unit(d);
    g[d] = (f(x + e) - f(x - e)) / (2 * step);
  }
  return g.normalized();
}

struct CloudFigures {
  double min_distance = 0, largest_hole = 0;  //!< in spacings
};

//! The checks every cloud passes: spacing, holes (≤ 1.2 spacings; measured 0.83–1.04 over
//! the shapes below, the largest next to boundaries), points on the shape, unit normals
//! along ∇F of the shape's implicit function F (outward where F grows).
template <int D>
CloudFigures check_cloud(const SurfaceShape<D>& shape, const PointSample<D>& cloud, double spacing,
                         const std::vector<Vec<D>>& probes, const Implicit<D>& f) {
  EXPECT_EQ(cloud.normals.size(), cloud.size());
  EXPECT_EQ(cloud.boundary.size(), cloud.size());
  CloudFigures figures;
  figures.min_distance = min_distance(cloud.points) / spacing;
  EXPECT_GE(figures.min_distance * spacing, spacing - 1e-12) << shape.describe();
  figures.largest_hole = largest_hole(cloud.points, probes) / spacing;
  EXPECT_LE(figures.largest_hole, 1.2) << shape.describe();
  double worst_error = 0.0, worst_normal = 0.0, worst_unit = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    worst_error = std::max(worst_error, shape.surface_error(cloud.points[i]));
    worst_unit = std::max(worst_unit, std::abs(cloud.normals[i].norm() - 1.0));
    if (f)
      worst_normal = std::max(worst_normal,
                              (cloud.normals[i] - implicit_normal<D>(f, cloud.points[i])).norm());
  }
  EXPECT_LE(worst_error, 1e-10) << shape.describe();
  EXPECT_LE(worst_unit, 1e-12) << shape.describe();
  EXPECT_LE(worst_normal, 1e-6) << shape.describe();
  return figures;
}

std::vector<Vec3> random_on_sphere(const Vec3& c, double r, int n, SampleRandom& random,
                                   const std::function<bool(const Vec3&)>& keep = nullptr) {
  std::vector<Vec3> out;
  while (static_cast<int>(out.size()) < n) {
    const Vec3 g(2 * random.uniform() - 1, 2 * random.uniform() - 1, 2 * random.uniform() - 1);
    if (g.norm() > 1.0 || g.norm() < 1e-3) continue;
    const Vec3 x = c + r * g.normalized();
    if (!keep || keep(x)) out.push_back(x);
  }
  return out;
}

TEST(SurfaceShapes, SphereCloudIsSpacedWithoutHoles) {
  const Vec3 c(0.5, -0.25, 1.0);
  const auto sphere = make_cut_sphere<3>(c, 1.5, {});
  const double s = 0.08;
  const auto cloud = sphere->sample({s, 7});
  SampleRandom random(11);
  const auto f = check_cloud<3>(*sphere, cloud, s, random_on_sphere(c, 1.5, 20000, random),
                                [&](const Vec3& x) { return (x - c).squaredNorm() - 2.25; });
  // Measured: nearest pair 1.000 s, largest hole 0.93 s, 4043 points.
  EXPECT_LT(f.largest_hole, 1.0);
  for (auto b : cloud.boundary) EXPECT_EQ(b, 0);
  EXPECT_EQ(sphere->describe(), "sphere of radius 1.5 about (0.5, -0.25, 1)");
}

TEST(SurfaceShapes, SphereErrorIsEquation13AndProjectionIsRadial) {
  const auto sphere = make_cut_sphere<3>(Vec3::Zero(), 2.0, {});
  const Vec3 x(0.0, 3.0, 0.0);
  EXPECT_NEAR(sphere->surface_error(x), (9.0 - 4.0) / 4.0, 1e-15);  // |‖x‖² − r²|/r²
  EXPECT_LT((sphere->project(x) - Vec3(0, 2, 0)).norm(), 1e-15);
  EXPECT_LT((sphere->normal(x) - Vec3(0, 1, 0)).norm(), 1e-15);
}

TEST(SurfaceShapes, HemisphereRimIsTheBoundary) {
  // The paper's deforming hemisphere (§3.7.2): the unit sphere, z ≥ 0.
  const auto hemisphere = make_cut_sphere<3>(Vec3::Zero(), 1.0, {Vec3(0, 0, 1)});
  const double s = 0.06;
  const auto cloud = hemisphere->sample({s, 3});
  SampleRandom random(5);
  check_cloud<3>(
      *hemisphere, cloud, s,
      random_on_sphere(Vec3::Zero(), 1.0, 20000, random, [](const Vec3& x) { return x.z() >= 0; }),
      [](const Vec3& x) { return x.squaredNorm() - 1.0; });
  std::vector<Vec3> rim;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const double z = cloud.points[i].z();
    if (cloud.boundary[i]) {
      EXPECT_LE(std::abs(z), 1e-12);
      rim.push_back(cloud.points[i]);
    } else {
      EXPECT_GT(z, 0.5 * s);  // interior points keep off the rim
    }
  }
  // The rim is covered: every point of it within 0.6 spacings of a rim point.
  std::vector<Vec3> circle;
  for (int k = 0; k < 2000; ++k)
    circle.emplace_back(std::cos(k * pi / 1000), std::sin(k * pi / 1000), 0);
  EXPECT_LE(largest_hole(rim, circle), 0.6 * s);
  EXPECT_NEAR(static_cast<double>(rim.size()), 2 * pi / s, 2.0);
  // Projections from below the rim land on it; errors there are distances.
  EXPECT_LT((hemisphere->project(Vec3(2, 0, -0.1)) - Vec3(1, 0, 0)).norm(), 1e-15);
  EXPECT_NEAR(hemisphere->surface_error(Vec3(1, 0, -0.1)), 0.1, 1e-15);
}

TEST(SurfaceShapes, QuarterSphereHasTwoRimsMeetingAtThePoles) {
  // The paper's rotating quarter sphere (§3.7.1): x ≥ 0 and y ≥ 0.
  const auto quarter = make_cut_sphere<3>(Vec3::Zero(), 1.0, {Vec3(1, 0, 0), Vec3(0, 1, 0)});
  const double s = 0.05;
  const auto cloud = quarter->sample({s, 1});
  SampleRandom random(9);
  check_cloud<3>(*quarter, cloud, s,
                 random_on_sphere(Vec3::Zero(), 1.0, 20000, random,
                                  [](const Vec3& x) { return x.x() >= 0 && x.y() >= 0; }),
                 [](const Vec3& x) { return x.squaredNorm() - 1.0; });
  int poles = 0;
  std::vector<Vec3> rim;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Vec3& x = cloud.points[i];
    EXPECT_GE(x.x(), -1e-12);
    EXPECT_GE(x.y(), -1e-12);
    if (cloud.boundary[i]) {
      EXPECT_LE(std::min(std::abs(x.x()), std::abs(x.y())), 1e-12);
      poles += (x - Vec3(0, 0, 1)).norm() < 1e-12 || (x - Vec3(0, 0, -1)).norm() < 1e-12;
      rim.push_back(x);
    } else {
      EXPECT_GT(std::min(x.x(), x.y()), 0.5 * s);
    }
  }
  EXPECT_EQ(poles, 2);
  std::vector<Vec3> edges;
  for (int k = 0; k <= 1000; ++k) {
    const double t = -0.5 * pi + k * pi / 1000;
    edges.emplace_back(std::cos(t), 0, std::sin(t));
    edges.emplace_back(0, std::cos(t), std::sin(t));
  }
  EXPECT_LE(largest_hole(rim, edges), 0.6 * s);
}

TEST(SurfaceShapes, EllipsoidClosestPointsAndCloud) {
  const Vec3 c(0, 0, 0.5), a(1.5, 1.0, 0.6);
  const auto ellipsoid = make_ellipsoid_shape<3>(c, a);
  // Closest points: on the surface, and x − p along the normal there.
  SampleRandom random(3);
  for (int k = 0; k < 200; ++k) {
    const Vec3 x = c + Vec3(3 * random.uniform() - 1.5, 2 * random.uniform() - 1,
                            1.2 * random.uniform() - 0.6) *
                           1.3;
    const Vec3 p = ellipsoid->project(x), q = (p - c).cwiseQuotient(a);
    EXPECT_NEAR(q.squaredNorm(), 1.0, 1e-13);
    const Vec3 n = ellipsoid->normal(x);
    EXPECT_LT((x - p).cross(n).norm(), 1e-12 + 1e-12 * (x - p).norm());
  }
  const double s = 0.06;
  const auto cloud = ellipsoid->sample({s, 2});
  std::vector<Vec3> probes;
  for (const Vec3& d : random_on_sphere(Vec3::Zero(), 1.0, 20000, random))
    probes.push_back(ellipsoid->project(c + a.cwiseProduct(d)));
  check_cloud<3>(*ellipsoid, cloud, s, probes,
                 [&](const Vec3& x) { return (x - c).cwiseQuotient(a).squaredNorm() - 1.0; });
}

TEST(SurfaceShapes, TorusErrorIsEquation15) {
  // The paper's torus, c = 3, a = 1 (§3.7.4).
  const auto torus = make_torus_shape(Vec3::Zero(), 3.0, 1.0);
  auto F = [](const Vec3& x) {
    const double rho = std::hypot(x.x(), x.y());
    return (3.0 - rho) * (3.0 - rho) + x.z() * x.z() - 1.0;
  };
  EXPECT_NEAR(torus->surface_error(Vec3(4.5, 0, 0)), std::abs(F(Vec3(4.5, 0, 0))), 1e-15);
  EXPECT_LT((torus->project(Vec3(0, 4.5, 0.0)) - Vec3(0, 4, 0)).norm(), 1e-15);
  const double s = 0.15;
  const auto cloud = torus->sample({s, 4});
  SampleRandom random(8);
  std::vector<Vec3> probes;
  for (int k = 0; k < 20000; ++k) {
    const double u = 2 * pi * random.uniform(), v = 2 * pi * random.uniform();
    probes.emplace_back((3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u),
                        std::sin(v));
  }
  check_cloud<3>(*torus, cloud, s, probes, F);
}

// §4.2.2: pipe radius 0.25, arc radius 0.75, here over 180°; each of the three halves.
TEST(SurfaceShapes, HalfPipeEdgesAndEndsAreTheBoundary) {
  const double rho = 0.25, R = 0.75, half = 0.5 * pi;
  const double s = 0.03;
  auto at = [&](double t, double p) {
    return Vec3((R + rho * std::cos(p)) * std::cos(t), rho * std::sin(p),
                (R + rho * std::cos(p)) * std::sin(t));
  };
  const std::pair<HalfPipeSide, double> sides[] = {{HalfPipeSide::inner, 0.5 * pi},
                                                   {HalfPipeSide::outer, -0.5 * pi},
                                                   {HalfPipeSide::upper, 0.0}};
  for (const auto& [side, phi0] : sides) {
    SCOPED_TRACE(phi0);
    const auto pipe = make_half_pipe_shape(rho, R, 2 * half, side);
    const auto cloud = pipe->sample({s, 6});
    SampleRandom random(4);
    std::vector<Vec3> probes, rims;
    for (int k = 0; k < 20000; ++k)
      probes.push_back(at(half * (2 * random.uniform() - 1), phi0 + pi * random.uniform()));
    for (int k = 0; k <= 500; ++k) {
      const double t = half * (2.0 * k / 500 - 1), p = phi0 + pi * k / 500;
      for (const Vec3& x : {at(t, phi0), at(t, phi0 + pi), at(-half, p), at(half, p)})
        rims.push_back(x);
    }
    check_cloud<3>(*pipe, cloud, s, probes, [&](const Vec3& x) {
      const double r = std::hypot(x.x(), x.z());
      return (R - r) * (R - r) + x.y() * x.y() - rho * rho;
    });
    // In the meridian plane the half kept has its offset from the centre line within 90° of
    // the direction φ0 + π/2; the edges are on the cut, the ends at x = 0.
    const auto offsets = [&](const Vec3& x) {
      const double r = std::hypot(x.x(), x.z()), middle = phi0 + 0.5 * pi;
      const double along = (r - R) * std::cos(middle) + x.y() * std::sin(middle);  // ≥ 0 kept
      return std::pair{along, std::min(std::abs(along), std::abs(x.x()))};
    };
    std::vector<Vec3> flagged;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const Vec3& x = cloud.points[i];
      const auto [along, off] = offsets(x);
      EXPECT_GE(along, -1e-12);
      if (cloud.boundary[i]) {
        EXPECT_LE(off, 1e-12) << x.transpose();
        flagged.push_back(x);
      } else {
        EXPECT_GT(off, 0.5 * s) << x.transpose();
      }
    }
    EXPECT_LE(largest_hole(flagged, rims), 0.6 * s);
  }
}

TEST(SurfaceShapes, ImplicitBlobsProjectByNewtonAndPointOutward) {
  const std::vector<Vec3> centers{Vec3(0, 0, 0), Vec3(0.9, 0, 0), Vec3(0.4, 0.6, 0.2)};
  const std::vector<double> radii{0.6, 0.5, 0.4};
  const double level = 0.5;
  const auto blobs = make_implicit_blobs<3>(centers, radii, level);
  auto f = [&](const Vec3& x) {
    double v = -level;
    for (int k = 0; k < 3; ++k)
      v += std::exp(-(x - centers[k]).squaredNorm() / (radii[k] * radii[k]));
    return v;
  };
  const double s = 0.04;
  const auto cloud = blobs->sample({s, 5});
  SampleRandom random(6);
  std::vector<Vec3> probes;
  while (probes.size() < 20000) {
    const Vec3 x(3 * random.uniform() - 1.2, 2.4 * random.uniform() - 1.2,
                 2.4 * random.uniform() - 1.2);
    const Vec3 p = blobs->project(x);
    if (std::abs(f(p)) < 1e-12) probes.push_back(p);
  }
  check_cloud<3>(*blobs, cloud, s, probes, [&](const Vec3& x) { return -f(x); });
  for (const Vec3& x : cloud.points) EXPECT_LT(std::abs(f(x)), 1e-13);
}

//! An OBJ file of a mesh.
void write_obj(const std::filesystem::path& path, const SurfaceMesh& m) {
  std::ofstream out(path);
  out.precision(17);
  for (const auto& v : m.vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& t : m.triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

class SurfaceShapeFiles : public ::testing::Test {
 protected:
  std::filesystem::path dir;
  void SetUp() override {
    dir = std::filesystem::temp_directory_path() /
          ("pellicle_surface_shapes_" +
           std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::create_directories(dir);
  }
  void TearDown() override { std::filesystem::remove_all(dir); }

  //! The shape a TOML table describes, and the problems found reading it.
  template <int D>
  std::pair<SurfaceShapePtr<D>, std::string> read(const std::string& text) {
    const toml::table table = toml::parse(std::string_view(text), std::string_view("shape.toml"));
    ProblemList problems{"shape.toml", {}};
    SurfaceShapePtr<D> shape;
    {
      TomlParameters in(table, "surface.shape", problems);
      shape = make_surface_shape<D>(in, dir.string());
    }
    std::string messages;
    for (const auto& p : problems.problems) messages += p.format() + "\n";
    return {std::move(shape), messages};
  }
};

TEST_F(SurfaceShapeFiles, OpenMeshBoundaryIsItsPerimeter) {
  write_obj(dir / "patch.obj",
            make_rectangle_patch(Vec3::Zero(), Vec3(2, 0, 0), Vec3(0, 1, 0), 0.25));
  auto [mesh, problems] = read<3>("kind = \"mesh\"\nfile = \"patch.obj\"\n");
  ASSERT_TRUE(mesh) << problems;
  EXPECT_EQ(problems, "");
  const double s = 0.05;
  const auto cloud = mesh->sample({s, 2});
  SampleRandom random(2);
  std::vector<Vec3> probes, perimeter;
  for (int k = 0; k < 20000; ++k) probes.emplace_back(2 * random.uniform(), random.uniform(), 0);
  for (int k = 0; k <= 1000; ++k) {
    const double u = k / 1000.0;
    for (const Vec3& x : {Vec3(2 * u, 0, 0), Vec3(2 * u, 1, 0), Vec3(0, u, 0), Vec3(2, u, 0)})
      perimeter.push_back(x);
  }
  check_cloud<3>(*mesh, cloud, s, probes, [](const Vec3& x) { return x.z(); });
  std::vector<Vec3> flagged;
  int corners = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Vec3& x = cloud.points[i];
    const double off = std::min({x.x(), 2 - x.x(), x.y(), 1 - x.y()});
    if (cloud.boundary[i]) {
      EXPECT_LE(std::abs(off), 1e-12) << x.transpose();
      flagged.push_back(x);
      corners += std::min(x.x(), 2 - x.x()) < 1e-12 && std::min(x.y(), 1 - x.y()) < 1e-12;
    } else {
      EXPECT_GT(off, 0.5 * s) << x.transpose();
    }
  }
  EXPECT_EQ(corners, 4);
  EXPECT_LE(largest_hole(flagged, perimeter), 0.6 * s);
  EXPECT_LT((mesh->project(Vec3(0.5, 0.5, 0.3)) - Vec3(0.5, 0.5, 0)).norm(), 1e-15);
  EXPECT_LT((mesh->project(Vec3(2.5, 0.5, 0.0)) - Vec3(2, 0.5, 0)).norm(), 1e-15);
}

TEST_F(SurfaceShapeFiles, ClosedMeshNormalsAreItsTriangles) {
  const SurfaceMesh sphere = make_ellipsoid(Vec3::Zero(), Vec3::Ones(), 0.3);
  write_obj(dir / "ball.obj", sphere);
  auto [mesh, problems] = read<3>("kind = \"mesh\"\nfile = \"ball.obj\"\n");
  ASSERT_TRUE(mesh) << problems;
  const double s = 0.08;
  const auto cloud = mesh->sample({s, 1});
  SampleRandom random(1);
  std::vector<Vec3> probes;
  for (int k = 0; k < 20000; ++k) {
    const auto& t = sphere.triangles[random.below(sphere.triangles.size())];
    double u = random.uniform(), v = random.uniform();
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Vec3 &a = sphere.vertices[t[0]], &b = sphere.vertices[t[1]], &c = sphere.vertices[t[2]];
    probes.push_back(a + u * (b - a) + v * (c - a));
  }
  check_cloud<3>(*mesh, cloud, s, probes, nullptr);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Vec3& x = cloud.points[i];
    EXPECT_EQ(cloud.boundary[i], 0);
    // The triangle the point lies on, by brute force, gives its normal; it points outward.
    double nearest = 1e300;
    Vec3 n = Vec3::Zero();
    for (const auto& t : sphere.triangles) {
      const Vec3 &a = sphere.vertices[t[0]], &b = sphere.vertices[t[1]], &c = sphere.vertices[t[2]];
      const Vec3 m = (b - a).cross(c - a).normalized();
      const Vec3 w = x - a;
      const double u = (c - a).cross(m).dot(w) / (c - a).cross(m).dot(b - a);
      const double v = (b - a).cross(m).dot(w) / (b - a).cross(m).dot(c - a);
      const double distance = std::abs(m.dot(w));
      if (u >= -1e-9 && v >= -1e-9 && u + v <= 1 + 1e-9 && distance < nearest)
        nearest = distance, n = m;
    }
    EXPECT_LT(nearest, 1e-12);
    EXPECT_LT((cloud.normals[i] - n).norm(), 1e-9) << x.transpose();
    EXPECT_GT(cloud.normals[i].dot(x), 0.9);
  }
}

TEST(SurfaceShapes, CircleArcHasTwoBoundaryPoints) {
  const Vec2 c(1, 2);
  const auto arc = make_cut_sphere<2>(c, 0.5, {Vec2(0, 1)});  // the upper half
  const double s = 0.02;
  const auto cloud = arc->sample({s, 3});
  SampleRandom random(2);
  std::vector<Vec2> probes;
  for (int k = 0; k < 5000; ++k) {
    const double t = pi * random.uniform();
    probes.push_back(c + 0.5 * Vec2(std::cos(t), std::sin(t)));
  }
  check_cloud<2>(*arc, cloud, s, probes,
                 [&](const Vec2& x) { return (x - c).squaredNorm() - 0.25; });
  std::vector<Vec2> ends;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    EXPECT_GE(cloud.points[i].y() - c.y(), -1e-12);
    if (cloud.boundary[i]) ends.push_back(cloud.points[i]);
  }
  ASSERT_EQ(ends.size(), 2u);
  EXPECT_LT(std::min((ends[0] - Vec2(1.5, 2)).norm(), (ends[0] - Vec2(0.5, 2)).norm()), 1e-12);
  EXPECT_LT((ends[0] - ends[1]).norm() - 1.0, 1e-12);
  // A whole circle has no boundary.
  const auto whole = make_cut_sphere<2>(c, 0.5, {})->sample({s, 3});
  for (auto b : whole.boundary) EXPECT_EQ(b, 0);
  EXPECT_NEAR(static_cast<double>(whole.size()), pi / s, 0.2 * pi / s);
}

TEST(SurfaceShapes, EllipseAndBlobsIn2D) {
  const Vec2 c(0, 0), a(2.0, 0.5);
  const auto ellipse = make_ellipsoid_shape<2>(c, a);
  const double s = 0.02;
  SampleRandom random(12);
  std::vector<Vec2> probes;
  for (int k = 0; k < 5000; ++k) {
    const double t = 2 * pi * random.uniform();
    probes.push_back(ellipse->project(Vec2(a.x() * std::cos(t), a.y() * std::sin(t))));
  }
  check_cloud<2>(*ellipse, ellipse->sample({s, 1}), s, probes,
                 [&](const Vec2& x) { return x.cwiseQuotient(a).squaredNorm() - 1; });

  const std::vector<Vec2> centers{Vec2(0, 0), Vec2(0.7, 0.2)};
  const std::vector<double> radii{0.5, 0.35};
  const auto blobs = make_implicit_blobs<2>(centers, radii, 0.4);
  auto f = [&](const Vec2& x) {
    return std::exp(-x.squaredNorm() / 0.25) + std::exp(-(x - centers[1]).squaredNorm() / 0.1225) -
           0.4;
  };
  probes.clear();
  while (probes.size() < 5000) {
    const Vec2 p = blobs->project(Vec2(2.4 * random.uniform() - 1, 2 * random.uniform() - 1));
    if (std::abs(f(p)) < 1e-12) probes.push_back(p);
  }
  check_cloud<2>(*blobs, blobs->sample({s, 1}), s, probes, [&](const Vec2& x) { return -f(x); });
}

TEST(SurfaceShapes, SameSeedSameCloudOtherSeedOtherCloud) {
  const auto torus = make_torus_shape(Vec3::Zero(), 1.0, 0.3);
  const auto a = torus->sample({0.05, 42}), b = torus->sample({0.05, 42});
  const auto c = torus->sample({0.05, 43});
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a.points[i], b.points[i]);
  std::size_t shared = 0;  // points of c that a also has
  for (const auto& x : c.points)
    for (const auto& y : a.points) shared += (x - y).norm() < 1e-9;
  EXPECT_EQ(shared, 0u);
  EXPECT_NEAR(static_cast<double>(c.size()), static_cast<double>(a.size()), 0.03 * a.size());
}

TEST(SurfaceShapes, PaperPointCountsOnTheUnitSphere) {
  // Tables 2 and 4: smoothing lengths h and initial point counts N on the unit sphere.
  // Measured with s = kPaperSpacingFactor h (seed 1): 467, 1882, 7492, 29941.
  const auto sphere = make_cut_sphere<3>(Vec3::Zero(), 1.0, {});
  const std::pair<double, double> table[] = {{0.4, 480}, {0.2, 1806}, {0.1, 7446}, {0.05, 30054}};
  for (const auto& [h, n] : table) {
    const auto cloud = sphere->sample({kPaperSpacingFactor * h, 1});
    EXPECT_NEAR(static_cast<double>(cloud.size()), n, 0.1 * n) << "h = " << h;
  }
}

TEST_F(SurfaceShapeFiles, ShapesReadFromTables) {
  auto [sphere, p1] = read<3>(
      "kind = \"sphere\"\ncenter = [0, 0, 0]\nradius = 2\n"
      "keep = [[0, 0, 1]]\n");
  ASSERT_TRUE(sphere) << p1;
  EXPECT_EQ(p1, "");
  EXPECT_EQ(sphere->describe(),
            "sphere of radius 2 about (0, 0, 0) cut to n·(x − c) ≥ 0 for n = (0, 0, 1)");
  auto [pipe, p2] = read<3>("kind = \"half-pipe\"\narc_angle = 90\n");
  ASSERT_TRUE(pipe) << p2;
  EXPECT_EQ(pipe->describe(),
            "inner half pipe of radius 0.25 along an arc of radius 0.75 spanning 90 degrees");
  auto [blobs, p3] = read<2>(
      "kind = \"implicit-blobs\"\ncenters = [[0, 0], [1, 0]]\n"
      "radii = [0.5, 0.5]\nlevel = 0.3\n");
  ASSERT_TRUE(blobs) << p3;
  EXPECT_EQ(p3, "");
  auto [torus, p4] = read<3>(
      "kind = \"torus\"\ncenter = [0, 0, 0]\nmajor_radius = 3\n"
      "minor_radius = 1\n");
  ASSERT_TRUE(torus) << p4;
  EXPECT_EQ(p4, "");
  EXPECT_EQ(surface_shape_kinds<2>(),
            (std::vector<std::string>{"circle", "ellipse", "implicit-blobs", "dumbbell"}));
  EXPECT_EQ(surface_shape_kinds<3>(),
            (std::vector<std::string>{"sphere", "ellipsoid", "torus", "half-pipe", "implicit-blobs",
                                      "mesh", "dumbbell", "tube"}));
}

TEST_F(SurfaceShapeFiles, BadInputNamesTheKey) {
  auto [unknown, p1] = read<3>("kind = \"spheroid\"\nradius = 1\n");
  EXPECT_FALSE(unknown);
  EXPECT_EQ(
      p1,
      "shape.toml:1:8: surface.shape.kind: expected one of \"sphere\", \"ellipsoid\", "
      "\"torus\", \"half-pipe\", \"implicit-blobs\", \"mesh\", \"dumbbell\" or \"tube\", found the "
      "string "
      "\"spheroid\"\n");
  auto [circle3, p2] = read<3>("kind = \"circle\"\n");  // a 2D kind in 3D
  EXPECT_FALSE(circle3);
  EXPECT_NE(p2.find("surface.shape.kind: expected one of"), std::string::npos) << p2;

  auto [negative, p3] = read<3>("kind = \"sphere\"\ncenter = [0, 0, 0]\nradius = -1\n");
  EXPECT_EQ(p3,
            "shape.toml:3:10: surface.shape.radius: expected a number > 0, found the integer -1\n");
  auto [missing, p4] = read<3>("kind = \"torus\"\ncenter = [0, 0, 0]\nmajor_radius = 3\n");
  EXPECT_NE(p4.find("surface.shape.minor_radius: expected a number > 0, found nothing (required)"),
            std::string::npos)
      << p4;
  auto [fat, p5] = read<3>(
      "kind = \"torus\"\ncenter = [0, 0, 0]\nmajor_radius = 1\n"
      "minor_radius = 2\n");
  EXPECT_NE(p5.find("surface.shape.minor_radius: expected minor_radius < major_radius"),
            std::string::npos)
      << p5;
  auto [empty, p6] = read<3>(
      "kind = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\n"
      "keep = [[0, 0, 1], [0, 0, -1]]\n");
  EXPECT_NE(p6.find("surface.shape.keep: expected cuts that leave part of the shape"),
            std::string::npos)
      << p6;
  auto [zero, p7] = read<2>("kind = \"circle\"\ncenter = [0, 0]\nradius = 1\nkeep = [[0, 0]]\n");
  EXPECT_NE(p7.find("surface.shape.keep: expected non-zero normals"), std::string::npos) << p7;
  auto [blobs, p8] = read<3>(
      "kind = \"implicit-blobs\"\ncenters = [[0, 0, 0], [1, 0, 0]]\n"
      "radii = [0.5]\nlevel = 1.5\n");
  EXPECT_NE(p8.find("surface.shape.radii: expected one radius per centre (2), found 1"),
            std::string::npos)
      << p8;
  EXPECT_NE(p8.find("surface.shape.level: expected a number in (0, 1), found the number 1.5"),
            std::string::npos)
      << p8;
  auto [pipe, p9] =
      read<3>("kind = \"half-pipe\"\npipe_radius = 1\narc_angle = 400\nside = \"left\"\n");
  EXPECT_NE(p9.find("surface.shape.arc_angle: expected a number in (0, 360)"), std::string::npos)
      << p9;
  EXPECT_NE(p9.find("surface.shape.pipe_radius: expected pipe_radius < arc_radius"),
            std::string::npos)
      << p9;
  EXPECT_NE(p9.find("surface.shape.side: expected one of \"inner\", \"outer\" or \"upper\", found "
                    "the string \"left\""),
            std::string::npos)
      << p9;
  auto [no_file, p10] = read<3>("kind = \"mesh\"\nfile = \"nowhere.stl\"\n");
  EXPECT_FALSE(no_file);
  EXPECT_NE(p10.find("surface.shape.file: "), std::string::npos) << p10;
  EXPECT_NE(p10.find("cannot open the STL file"), std::string::npos) << p10;
  auto [typo, p11] = read<3>("kind = \"ellipsoid\"\ncenter = [0, 0, 0]\nsemi_axis = [1, 1, 1]\n");
  EXPECT_NE(p11.find("surface.shape.semi_axes: expected an array of 3 numbers"), std::string::npos)
      << p11;
  EXPECT_NE(p11.find("surface.shape.semi_axis: unknown key"), std::string::npos) << p11;
}

}  // namespace
}  // namespace pellicle
