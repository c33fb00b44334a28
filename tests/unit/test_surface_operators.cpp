// The meshfree surface machinery of Suchde & Kuhnert: neighbour search against brute force,
// normals by eq 4 and their orientation, GFDM stencils (eqs 17–27) exact for quadratics in
// the plane and converging on the sphere, curvature (eq 37), movement (eqs 2–3).
#include <gtest/gtest.h>

#include <omp.h>
#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <random>

#include "pellicle/core/error.hpp"
#include "pellicle/pointcloud/neighbour_search.hpp"
#include "pellicle/surface/frames.hpp"
#include "pellicle/surface/gfdm.hpp"
#include "pellicle/surface/movement.hpp"
#include "pellicle/surface/point_cloud.hpp"
#include "pellicle/surface/quadrature.hpp"
#include "pellicle/surface/sparse_system.hpp"
#include "pellicle/surface/spectrum.hpp"
#include "support/test_clouds.hpp"

namespace pellicle {
namespace {

//! Neighbours, frames (eq 4, oriented), stencils; with `refine` the second-order normals and
//! the stencils built again on them.
template <int D>
void prepare(PointCloud<D>& c, NeighbourLists& nb, SurfaceStencils<D>& st, bool refine) {
  NeighbourSearch<D> search;
  search.find(c, nb);
  estimate_frames(c, nb, FrameOptions{}, false);
  orient_consistently(c, nb);
  build_stencils(c, nb, GfdmOptions{}, st);
  if (refine) {
    refine_normals(c, nb, st);
    build_stencils(c, nb, GfdmOptions{}, st);
  }
}

template <int D>
std::vector<int> brute_force(const PointCloud<D>& c, std::size_t i) {
  std::vector<int> out;
  for (std::size_t j = 0; j < c.size(); ++j)
    if (j != i && (c.position[j] - c.position[i]).norm() <= c.smoothing_length[i])
      out.push_back(static_cast<int>(j));
  return out;
}

template <int D>
void expect_lists_match(const PointCloud<D>& c, const NeighbourLists& nb) {
  for (std::size_t i = 0; i < c.size(); ++i) {
    ASSERT_EQ(nb.index[nb.begin(i)], static_cast<int>(i));  // self first
    const std::vector<int> found(nb.index.begin() + nb.begin(i) + 1, nb.index.begin() + nb.end(i));
    ASSERT_EQ(found, brute_force(c, i)) << "point " << i;
  }
}

TEST(SurfaceNeighbours, MatchBruteForceWithVariableSmoothingLength) {
  auto c = test::jittered_sphere(1.0, 0.2);
  for (std::size_t i = 0; i < c.size(); ++i) c.smoothing_length[i] = 0.15 + 0.1 * c.position[i].z();
  NeighbourSearch<3> search(0.25);
  NeighbourLists nb;
  search.find(c, nb);
  expect_lists_match(c, nb);
  EXPECT_EQ(search.rebuilds(), 1);
  // Small moves keep the tree (searched with the drift added) and stay exact.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-0.002, 0.002);
  for (auto& x : c.position) x += Vec3(u(rng), u(rng), u(rng));
  search.find(c, nb);
  expect_lists_match(c, nb);
  EXPECT_EQ(search.rebuilds(), 1);
  // Larger moves, or new points, rebuild it.
  for (auto& x : c.position) x *= 1.2;
  search.find(c, nb);
  expect_lists_match(c, nb);
  EXPECT_EQ(search.rebuilds(), 2);
  c.add_point(Vec3(0, 0, 1.3), 0.2, false);
  search.find(c, nb);
  expect_lists_match(c, nb);
  EXPECT_EQ(search.rebuilds(), 3);
}

TEST(SurfaceFrames, PlaneNormalsExactAndSphereOutward) {
  auto plane = test::random_patch(800, 0.25, 0.3);
  NeighbourSearch<3> search;
  NeighbourLists nb;
  search.find(plane, nb);
  estimate_frames(plane, nb, FrameOptions{}, false);
  orient_consistently(plane, nb);
  const Vec3 exact(0, -std::sin(0.3), std::cos(0.3));
  for (std::size_t i = 0; i < plane.size(); ++i) {
    EXPECT_NEAR(std::abs(plane.normal(i).dot(exact)), 1.0, 1e-12) << i;
    EXPECT_NEAR(plane.frame[i].determinant(), 1.0, 1e-12);
    EXPECT_GT(plane.normal(i).dot(plane.normal(0)), 0.0);  // one side
  }

  auto sphere = test::jittered_sphere(1.0, 0.2);
  NeighbourSearch<3> s2;
  s2.find(sphere, nb);
  estimate_frames(sphere, nb, FrameOptions{}, false);
  orient_consistently(sphere, nb);
  double worst = 0.0;
  for (std::size_t i = 0; i < sphere.size(); ++i) {
    const double cosine = sphere.normal(i).dot(sphere.position[i].normalized());
    worst = std::max(worst, std::acos(std::min(1.0, cosine)));
    EXPECT_TRUE((sphere.frame[i].transpose() * sphere.frame[i]).isIdentity(1e-12));
  }
  EXPECT_LT(worst, 0.02);  // outward everywhere, within about a degree (measured 0.4°)
  // eq 5: a second estimate keeps every side, even starting from flipped frames.
  for (auto& f : sphere.frame) flip_normal<3>(f);
  estimate_frames(sphere, nb, FrameOptions{}, true);
  for (std::size_t i = 0; i < sphere.size(); ++i)
    EXPECT_LT(sphere.normal(i).dot(sphere.position[i]), 0.0) << i;
}

// Quadratic u(x, y) on a tilted plane: the stencils differentiate it exactly (eq 18).
TEST(SurfaceGfdm, ExactForQuadraticsInThePlane) {
  const double tilt = 0.4;
  auto c = test::random_patch(1500, 0.2, tilt);
  NeighbourLists nb;
  SurfaceStencils<3> st;
  prepare(c, nb, st, false);
  const Vec3 e1(1, 0, 0), e2(0, std::cos(tilt), std::sin(tilt));
  std::vector<double> u(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double a = c.position[i].dot(e1), b = c.position[i].dot(e2);
    u[i] = 1 + 2 * a - 3 * b + 0.5 * a * a + 4 * a * b - 1.5 * b * b;
  }
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (std::abs(c.position[i].x()) > 0.7 || std::abs(c.position[i].dot(e2)) > 0.7) continue;
    const double a = c.position[i].dot(e1), b = c.position[i].dot(e2);
    const Vec3 exact = (2 + a + 4 * b) * e1 + (-3 + 4 * a - 3 * b) * e2;
    EXPECT_LT((surface_gradient(nb, st, i, u) - exact).norm(), 1e-9) << i;
    EXPECT_NEAR(laplace_beltrami(nb, st, i, u), 1.0 - 3.0, 1e-8) << i;
  }
}

// At boundary points the zero-flux Laplacian is exact for quadratics with no normal flux
// there: u = x² + (y + 1)² on a patch whose edge y = −1 is the boundary (ν = −e_y).
TEST(SurfaceGfdm, ZeroFluxLaplacianAtTheBoundary) {
  auto c = test::random_patch(1500, 0.2);
  for (auto& x : c.position) x.y() = std::max(x.y(), -0.97);  // clear of the edge row
  for (int k = 0; k <= 40; ++k) c.add_point(Vec3(-1.0 + k * 0.05, -1.0, 0.0), 0.2, true);
  NeighbourLists nb;
  SurfaceStencils<3> st;
  prepare(c, nb, st, false);
  std::vector<double> u(c.size()), v(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Vec3& x = c.position[i];
    u[i] = x.x() * x.x() + (x.y() + 1.0) * (x.y() + 1.0);
    v[i] = x.y();  // has flux through the edge
  }
  int checked = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!c.boundary[i] || std::abs(c.position[i].x()) > 0.7) continue;
    EXPECT_LT((c.boundary_normal[i] + Vec3::UnitY()).norm(), 1e-6) << i;
    double lu = 0.0, lv = 0.0;
    for (long k = nb.begin(i); k < nb.end(i); ++k) {
      lu += st.zero_flux_laplacian[k] * u[nb.index[k]];
      lv += st.zero_flux_laplacian[k] * v[nb.index[k]];
    }
    EXPECT_NEAR(lu, 4.0, 1e-8) << i;
    EXPECT_GT(std::abs(lv), 1.0) << i;  // a flux the stencil was told is zero shows
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

// A corner (x, y ≥ −1): zero flux through both edges means ∇u = 0 there, and the corner's
// fit has no slope at all; exact for quadratics with that property, and its centre
// coefficient negative (a free one-sided quadratic's is positive: docs/theory/surface-gfdm.md).
// Along the edges the centre coefficient is negative too.
TEST(SurfaceGfdm, ZeroFluxLaplacianAtACorner) {
  auto c = test::random_patch(1500, 0.2);
  for (auto& x : c.position) x = x.cwiseMax(Vec3(-0.97, -0.97, 0.0));
  for (int k = 0; k <= 40; ++k) c.add_point(Vec3(-1.0 + k * 0.05, -1.0, 0.0), 0.2, true);
  for (int k = 1; k <= 40; ++k) c.add_point(Vec3(-1.0, -1.0 + k * 0.05, 0.0), 0.2, true);
  NeighbourLists nb;
  SurfaceStencils<3> st;
  prepare(c, nb, st, false);
  std::vector<double> u(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double a = c.position[i].x() + 1.0, b = c.position[i].y() + 1.0;
    u[i] = a * a + a * b + 2.0 * b * b;  // Δu = 6, ∇u = 0 at the corner
  }
  std::size_t corner = 0;
  while ((c.position[corner] - Vec3(-1, -1, 0)).norm() > 1e-12) ++corner;
  EXPECT_EQ(c.corner[corner], 1);
  double lu = 0.0;
  for (long k = nb.begin(corner); k < nb.end(corner); ++k)
    lu += st.zero_flux_laplacian[k] * u[nb.index[k]];
  EXPECT_NEAR(lu, 6.0, 1e-8);
  int edges = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!c.boundary[i] || c.position[i].maxCoeff() > 0.7) continue;
    EXPECT_LT(st.zero_flux_laplacian[nb.begin(i)], 0.0) << c.position[i].transpose();
    edges += c.corner[i] ? 0 : 1;
  }
  EXPECT_GT(edges, 50);
}

// Δ_M (xy) = −6 xy/r², ∇_M · n = 2/r on a sphere. With the eq 4 normals alone the curvature
// error stalls at 3 % (their O(h) tilt on an uneven cloud); with the refined normals it
// falls as h² (2.3e-4, 5.7e-5, 1.4e-5). The Laplace–Beltrami stencil's own truncation error
// on an irregular cloud is first order (6.8e-3, 3.3e-3, 1.7e-3 relative).
struct SphereErrors {
  std::vector<double> laplacian, curvature;
};
SphereErrors sphere_errors(bool refine) {
  SphereErrors out;
  for (double h : {0.4, 0.2, 0.1}) {
    auto c = test::jittered_sphere(2.0, h);
    NeighbourLists nb;
    SurfaceStencils<3> st;
    prepare(c, nb, st, refine);
    std::vector<double> u(c.size()), kappa;
    for (std::size_t i = 0; i < c.size(); ++i) u[i] = c.position[i].x() * c.position[i].y();
    mean_curvature(c, nb, st, kappa);
    double e2 = 0, n2 = 0, k2 = 0;
    for (std::size_t i = 0; i < c.size(); ++i) {
      const double exact = -6.0 * u[i] / 4.0;
      e2 += std::pow(laplace_beltrami(nb, st, i, u) - exact, 2);
      n2 += exact * exact;
      k2 += std::pow(kappa[i] + 0.5, 2);
    }
    out.laplacian.push_back(std::sqrt(e2 / n2));
    out.curvature.push_back(std::sqrt(k2 / c.size()) / 0.5);
  }
  return out;
}

TEST(SurfaceGfdm, LaplaceBeltramiAndCurvatureConvergeOnTheSphere) {
  const SphereErrors plain = sphere_errors(false), refined = sphere_errors(true);
  for (int k = 0; k < 3; ++k)
    std::printf("h %.1f: Laplace-Beltrami %.3g (eq 4 normals %.3g), curvature %.3g (%.3g)\n",
                0.4 / (1 << k), refined.laplacian[k], plain.laplacian[k], refined.curvature[k],
                plain.curvature[k]);
  for (int k = 0; k < 2; ++k) {
    EXPECT_GT(std::log2(refined.laplacian[k] / refined.laplacian[k + 1]), 0.8);
    EXPECT_GT(std::log2(refined.curvature[k] / refined.curvature[k + 1]), 1.8);
  }
  EXPECT_LT(std::log2(plain.curvature[1] / plain.curvature[2]), 0.5);  // why refine exists
  EXPECT_LT(refined.laplacian.back(), 2e-3);
  EXPECT_LT(refined.curvature.back(), 2e-5);
}

// A curve in 2D: Δ of cos 2θ is −4 cos 2θ / r², curvature −1/r.
TEST(SurfaceGfdm, CurveOperatorsOnACircle) {
  auto c = test::jittered_circle(1.5, 400, 0.12);
  NeighbourLists nb;
  SurfaceStencils<2> st;
  prepare(c, nb, st, true);
  std::vector<double> u(c.size()), kappa;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double a = std::atan2(c.position[i].y(), c.position[i].x());
    u[i] = std::cos(2 * a);
  }
  mean_curvature(c, nb, st, kappa);
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_GT(c.normal(i).dot(c.position[i]), 0.0);
    EXPECT_NEAR(laplace_beltrami(nb, st, i, u), -4.0 * u[i] / 2.25, 0.02) << i;
    EXPECT_NEAR(kappa[i], -1.0 / 1.5, 0.005) << i;
  }
}

// (I − Δt Δ_M) u = b on a sphere, solved by BiCGSTAB: the residual is what was asked for.
TEST(SurfaceSparseSystem, ImplicitDiffusionSolve) {
  auto c = test::jittered_sphere(1.0, 0.2);
  NeighbourLists nb;
  SurfaceStencils<3> st;
  prepare(c, nb, st, false);
  const double dt = 0.05;
  SparseSystem system;
  system.values.resize(nb.index.size());
  std::vector<double> b(c.size()), u(c.size(), 0.0);
  for (std::size_t i = 0; i < c.size(); ++i) {
    for (long k = nb.begin(i); k < nb.end(i); ++k)
      system.values[k] = (k == nb.begin(i) ? 1.0 : 0.0) - dt * st.laplacian[k];
    b[i] = c.position[i].x() * c.position[i].y();
  }
  const auto report = system.solve(nb, b, u, LinearSolverOptions{1e-12, 200});
  EXPECT_LT(report.residual, 1e-12);
  // xy is an eigenfunction (eigenvalue −6): u = b/(1 + 6 Δt) up to the discretisation.
  double err = 0, norm = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    err += std::pow(u[i] - b[i] / (1 + 6 * dt), 2);
    norm += b[i] * b[i] / std::pow(1 + 6 * dt, 2);
  }
  EXPECT_LT(std::sqrt(err / norm), 5e-3);
}

// A row whose diagonal is not positive would amplify its point's value: refused, naming it.
TEST(SurfaceSparseSystem, NonPositiveDiagonalIsANumericalError) {
  NeighbourLists nb;
  nb.index = {0, 1, 1, 0};
  nb.offset = {0, 2, 4};
  SparseSystem system;
  system.values = {2.0, -1.0, -0.5, -1.0};  // row 1: diagonal −0.5
  std::vector<double> b{1.0, 1.0}, u{0.0, 0.0};
  try {
    system.solve(nb, b, u, LinearSolverOptions{});
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("row 1 of the implicit step has the diagonal -0.5"),
              std::string::npos)
        << e.what();
  }
}

// −Δ_M on the unit sphere: l(l + 1) = 0, 2 (×3), 6 (×5), 12 (×7).
SpectrumReport sphere_spectrum(double points_per_h2, double weight_exponent, int count);

TEST(SurfaceSpectrum, SphereEigenvalues) {
  const SpectrumReport r = sphere_spectrum(6.0, 8.0, 16);
  ASSERT_EQ(r.eigenvalues.size(), 16u);
  EXPECT_NEAR(r.eigenvalues[0], 0.0, 1e-8);
  for (int k = 1; k <= 3; ++k) EXPECT_NEAR(r.eigenvalues[k], 2.0, 0.02) << k;
  for (int k = 4; k <= 8; ++k) EXPECT_NEAR(r.eigenvalues[k], 6.0, 0.06) << k;
  for (int k = 9; k <= 15; ++k) EXPECT_NEAR(r.eigenvalues[k], 12.0, 0.12) << k;
  std::printf("eigenvalues:");
  for (double l : r.eigenvalues) std::printf(" %.4f", l);
  std::printf("\nlargest imaginary part %.3g\n", r.largest_imaginary);
}

// The weight's width decides whether the discrete operator has spurious modes: with
// W = exp(−2r²/h²) a cloud of 9 points per h² has negative eigenvalues of −Δ_M (growing
// modes of implicit diffusion); with the default exp(−8r²/h²) even 20 points per h² give
// exactly the sphere's spectrum (docs/theory/surface-gfdm.md has the whole table).
SpectrumReport sphere_spectrum(double points_per_h2, double weight_exponent, int count) {
  auto c = test::jittered_sphere(1.0, 0.2, points_per_h2);
  NeighbourSearch<3> search;
  NeighbourLists nb;
  SurfaceStencils<3> st;
  search.find(c, nb);
  estimate_frames(c, nb, FrameOptions{}, false);
  orient_consistently(c, nb);
  GfdmOptions g;
  g.weight_exponent = weight_exponent;
  build_stencils(c, nb, g, st);
  refine_normals(c, nb, st);
  build_stencils(c, nb, g, st);
  return laplace_beltrami_spectrum<3>(nb, st, count);
}

TEST(SurfaceSpectrum, BroadWeightsGiveSpuriousModesNarrowOnesDoNot) {
  EXPECT_LT(sphere_spectrum(9.0, 2.0, 10).eigenvalues.front(), -0.05);
  const SpectrumReport clean = sphere_spectrum(20.0, 8.0, 10);
  EXPECT_NEAR(clean.eigenvalues[0], 0.0, 1e-8);
  for (int k = 1; k <= 3; ++k) EXPECT_NEAR(clean.eigenvalues[k], 2.0, 0.01) << k;
  for (int k = 4; k <= 8; ++k) EXPECT_NEAR(clean.eigenvalues[k], 6.0, 0.01) << k;
  EXPECT_NEAR(clean.eigenvalues[9], 12.0, 0.1);
}

// One-ring areas integrate over the sphere: Σ A = 4π r², Σ A x² = 4π r⁴/3.
TEST(SurfaceQuadrature, SphereAreaAndSecondMoment) {
  for (double h : {0.2, 0.1}) {
    auto c = test::jittered_sphere(1.0, h);
    NeighbourLists nb;
    SurfaceStencils<3> st;
    prepare(c, nb, st, true);
    std::vector<double> area;
    point_areas(c, nb, area);
    double total = 0.0, moment = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i) {
      total += area[i];
      moment += area[i] * c.position[i].x() * c.position[i].x();
    }
    // Measured: −4.8e-4 and 1.7e-4 (area), −1.1e-3 and 3.2e-4 (moment) at h = 0.2, 0.1.
    EXPECT_NEAR(total / (4 * M_PI), 1.0, 3e-3) << h;
    EXPECT_NEAR(moment / (4 * M_PI / 3), 1.0, 3e-3) << h;
    std::printf("h %.1f: area / 4π − 1 = %.2e, second moment %.2e\n", h, total / (4 * M_PI) - 1,
                moment / (4 * M_PI / 3) - 1);
  }
}

// A point with too few neighbours stops the stencils and the frames with a NumericalError
// naming it, also when the loop that finds it runs on several threads.
TEST(SurfaceGfdm, IsolatedPointIsReportedFromAParallelLoop) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  auto c = test::jittered_sphere(1.0, 0.2);
  c.add_point(Vec3(0.0, 0.0, 5.0), 0.2, false);  // far off the sphere: no neighbours
  NeighbourSearch<3> search;
  NeighbourLists nb;
  search.find(c, nb);
  try {
    estimate_frames(c, nb, FrameOptions{}, false);
    FAIL() << "frames of an isolated point";
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.context().point, static_cast<long>(c.size() - 1));
    EXPECT_NE(std::string(e.what()).find("0 neighbours"), std::string::npos) << e.what();
  }
  c.position.back() = Vec3(0.0, 0.0, 1.0);  // on the pole, but its neighbours all dropped
  c.smoothing_length.back() = 1e-3;
  search.find(c, nb);
  SurfaceStencils<3> st;
  EXPECT_THROW(build_stencils(c, nb, GfdmOptions{}, st), NumericalError);
  omp_set_num_threads(threads);
}

// A rigid rotation: eq 2 spirals outward as (1 + ω²Δt²)^(n/2), eq 3 stays on the circle.
TEST(SurfaceMovement, SecondOrderKeepsRotatingPointsOnTheirCircle) {
  for (auto order : {MovementOrder::first, MovementOrder::second}) {
    PointCloud<2> c;
    c.add_point(Vec2(1, 0), 0.1, false);
    const double dt = 0.05;
    const int steps = static_cast<int>(std::round(2 * std::numbers::pi / dt));
    for (int s = 0; s < steps; ++s) {
      c.velocity[0] = Vec2(-c.position[0].y(), c.position[0].x());
      move_points(c, dt, order);
    }
    const double r = c.position[0].norm();
    if (order == MovementOrder::first)
      EXPECT_NEAR(r, std::pow(1 + dt * dt, steps / 2.0), 1e-12);
    else
      EXPECT_LT(std::abs(r - 1.0), 3e-3);  // measured: first-step error 1.25e-3 kept
  }
}

}  // namespace
}  // namespace pellicle
