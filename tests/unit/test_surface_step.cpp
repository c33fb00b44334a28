// A few steps of SurfaceSimulation (surface/simulation.hpp, Suchde & Kuhnert §3–4) on an
// irregular cloud on the unit sphere, against answers worked by hand:
//   movement   a constant velocity v translates every point by v Δt a step (eq 2 and eq 3
//              agree: v⁽ⁿ⁾ − v⁽ⁿ⁻¹⁾ = 0), so the cloud stays a unit sphere about the moved
//              centre, with the same normals and curvature. The velocity v = a x scales it:
//              eq 2 gives R⁽ⁿ⁺¹⁾ = R⁽ⁿ⁾ (1 + aΔt), eq 3 R⁽ⁿ⁺¹⁾ = R⁽ⁿ⁾ (1 + aΔt) +
//              ½ a (R⁽ⁿ⁾ − R⁽ⁿ⁻¹⁾) Δt after its first step, every point keeping its direction.
//   the PDE    eq 29, (φⁿ⁺¹ − φⁿ)/Δt + φⁿ⁺¹ ∇_M·vⁿ⁺¹ = α Δ_M φⁿ⁺¹ + k φⁿ⁺¹ + s. For a uniform φ
//              on a static cloud (Δ_M φ = 0, ∇_M·v = 0) this is φⁿ⁺¹ = (φⁿ/Δt + s)/(1/Δt − k),
//              exactly; a moving point keeps its φ when α = k = s = 0 and v is constant
//              (∇_M·v = 0); φ = z is an eigenfunction of Δ_M, Δ_M z = −2z, so diffusion
//              gives φⁿ = z/(1 + 2αΔt)ⁿ; on the sphere expanding with v = a x, ∇_M·v = 2a, so
//              a uniform φ without diffusion or reaction becomes φⁿ = 1/(1 + 2aΔt)ⁿ.
// The diffusion holds up to the GFDM Laplacian's error, bounded at the check well below the
// difference from a wrong step (explicit Euler, the exact flow, a mis-signed term).
#include <gtest/gtest.h>

#include <toml++/toml.h>

#include <cmath>

#include "pellicle/io/toml_parameters.hpp"
#include "pellicle/surface/pde.hpp"
#include "pellicle/surface/simulation.hpp"
#include "support/test_clouds.hpp"

namespace pellicle {
namespace {

constexpr double kH = 0.25;

std::unique_ptr<SurfacePde<3>> advection_diffusion(const std::string& table) {
  const toml::table parsed = toml::parse(std::string_view(table), std::string_view("case.toml"));
  ProblemList problems{"case.toml", {}};
  std::unique_ptr<SurfacePde<3>> pde;
  {
    TomlParameters in(parsed, "pde", problems);
    for (const auto& model : surface_pde_models<3>())
      if (model.name == "advection-diffusion") pde = model.make(in);
  }
  problems.throw_if_any();
  return pde;
}

//! The unit sphere's irregular cloud moved by the velocity formulas (vx, vy, vz), without
//! point management (so that no point is added or removed), carrying `pde` (or none).
std::unique_ptr<SurfaceSimulation<3>> sphere(const std::array<const char*, 3>& velocity, double dt,
                                             MovementOrder order,
                                             std::unique_ptr<SurfacePde<3>> pde = nullptr) {
  PointCloud<3> cloud = test::jittered_sphere(1.0, kH);
  std::vector<Vec3> outward(cloud.position);
  SurfaceSettings settings;
  settings.dt = dt;
  settings.end_time = 1.0;
  settings.movement = order;
  settings.manage = false;
  return std::make_unique<SurfaceSimulation<3>>(
      std::move(cloud), settings,
      std::array<PointFormula, 3>{PointFormula(velocity[0]), PointFormula(velocity[1]),
                                  PointFormula(velocity[2])},
      std::move(pde), &outward);
}

const std::vector<double>& phi(const SurfaceSimulation<3>& s) {
  return s.cloud().field(s.pde()->unknown());
}

TEST(SurfaceStep, ConstantVelocityTranslatesTheCloudRigidly) {
  const Vec3 v(0.5, -0.25, 1.0);
  const double dt = 0.05;
  const int steps = 4;
  for (const MovementOrder order : {MovementOrder::first, MovementOrder::second}) {
    SCOPED_TRACE(order == MovementOrder::first ? "eq 2" : "eq 3");
    auto s = sphere({"0.5", "-0.25", "1.0"}, dt, order);
    const std::vector<Vec3> start = s->cloud().position;
    std::vector<Vec3> normals(start.size());
    for (std::size_t i = 0; i < start.size(); ++i) normals[i] = s->cloud().normal(i);
    const std::vector<double> curvature = s->curvature();
    for (int n = 0; n < steps; ++n) s->step();
    EXPECT_NEAR(s->time(), steps * dt, 1e-15);
    const Vec3 shift = steps * dt * v;
    ASSERT_EQ(s->cloud().size(), start.size());
    double worst_position = 0.0, worst_radius = 0.0, worst_normal = 0.0, worst_curvature = 0.0;
    for (std::size_t i = 0; i < start.size(); ++i) {
      const Vec3& x = s->cloud().position[i];
      worst_position = std::max(worst_position, (x - start[i] - shift).norm());
      worst_radius = std::max(worst_radius, std::abs((x - shift).norm() - 1.0));
      worst_normal = std::max(worst_normal, (s->cloud().normal(i) - normals[i]).norm());
      worst_curvature = std::max(worst_curvature, std::abs(s->curvature()[i] - curvature[i]));
    }
    // Round-off of four additions of v Δt to coordinates of order 1.
    EXPECT_LT(worst_position, 1e-14);
    EXPECT_LT(worst_radius, 1e-14);
    // Frames and curvature come from differences of positions, which the translation changes
    // by round-off only; the normals keep their side (eq 5).
    EXPECT_LT(worst_normal, 1e-12);
    EXPECT_LT(worst_curvature, 1e-11);
  }
}

TEST(SurfaceStep, LinearVelocityScalesTheSphereByEachMovementRule) {
  const double a = 0.5, dt = 0.1;
  const int steps = 3;
  for (const MovementOrder order : {MovementOrder::first, MovementOrder::second}) {
    SCOPED_TRACE(order == MovementOrder::first ? "eq 2" : "eq 3");
    auto s = sphere({"0.5 * x", "0.5 * y", "0.5 * z"}, dt, order);
    const std::vector<Vec3> start = s->cloud().position;
    // By hand: eq 2 gives 1.05, 1.1025, 1.157625; eq 3 gives 1.05, 1.10375, 1.16028125
    // (e^{0.15} = 1.161834 for the exact flow).
    double previous = 1.0, radius = 1.0;
    for (int n = 0; n < steps; ++n) {
      s->step();
      double next = radius * (1.0 + a * dt);
      if (order == MovementOrder::second && n > 0) next += 0.5 * a * (radius - previous) * dt;
      previous = radius;
      radius = next;
    }
    EXPECT_NEAR(radius, order == MovementOrder::first ? 1.157625 : 1.16028125, 1e-12);
    for (std::size_t i = 0; i < start.size(); ++i) {
      const Vec3& x = s->cloud().position[i];
      ASSERT_NEAR(x.norm(), radius, 1e-13) << "point " << i;
      ASSERT_LT((x / radius - start[i]).norm(), 1e-13) << "point " << i;
    }
  }
}

TEST(SurfaceStep, UniformFieldFollowsTheImplicitReactionStep) {
  // φ⁰ = 1, k = −2, s = 0.5, Δt = 0.1: φⁿ⁺¹ = (10 φⁿ + 0.5)/12, i.e. 0.875, 0.77083…,
  // 0.68403…; the diffusion (α = 0.3) of a uniform field is nothing.
  const double dt = 0.1, k = -2.0, source = 0.5;
  auto s = sphere({"0", "0", "0"}, dt, MovementOrder::second,
                  advection_diffusion("initial = \"1\"\ndiffusion = 0.3\nreaction = \"-2\"\n"
                                      "source = \"0.5\"\n"));
  double expected = 1.0;
  for (int n = 0; n < 3; ++n) {
    s->step();
    expected = (expected / dt + source) / (1.0 / dt - k);
    for (double value : phi(*s)) ASSERT_NEAR(value, expected, 1e-9) << "step " << n + 1;
  }
  EXPECT_NEAR(expected, 0.68402777777777778, 1e-15);
}

TEST(SurfaceStep, TranslatedPointsCarryTheirValues) {
  // Dφ/Dt = 0 and ∇_M·v = 0: each point keeps φ = its starting z, now z − v_z t.
  auto s = sphere({"0.5", "-0.25", "1.0"}, 0.05, MovementOrder::second,
                  advection_diffusion("initial = \"z\"\n"));
  const std::vector<Vec3> start = s->cloud().position;
  for (int n = 0; n < 4; ++n) s->step();
  for (std::size_t i = 0; i < start.size(); ++i) {
    ASSERT_NEAR(phi(*s)[i], start[i].z(), 1e-9) << "point " << i;
    ASSERT_NEAR(phi(*s)[i], s->cloud().position[i].z() - 0.2, 1e-9) << "point " << i;
  }
}

//! max_i |φ_i − expected(i)| / max_i |expected(i)|.
template <class F>
double relative_max_error(const SurfaceSimulation<3>& s, F&& expected) {
  double error = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < s.cloud().size(); ++i) {
    error = std::max(error, std::abs(phi(s)[i] - expected(i)));
    scale = std::max(scale, std::abs(expected(i)));
  }
  return error / scale;
}

TEST(SurfaceStep, DiffusionOfTheFirstHarmonicDecaysByTheImplicitFactor) {
  // φ = z, Δ_M z = −2z: φⁿ = z / (1 + 2αΔt)ⁿ = z / 1.1³ after three steps of α = 0.5,
  // Δt = 0.1. Explicit Euler would give 0.9³ z (3 % less), the exact flow e^{−0.3} z
  // (1.4 % less). The GFDM Laplacian of z on this cloud is −2z to about 0.1 %, which the
  // bound allows three times over.
  auto s = sphere({"0", "0", "0"}, 0.1, MovementOrder::second,
                  advection_diffusion("initial = \"z\"\ndiffusion = 0.5\n"));
  const std::vector<Vec3> x = s->cloud().position;
  for (int n = 0; n < 3; ++n) s->step();
  const double factor = 1.0 / std::pow(1.1, 3);
  const double error = relative_max_error(*s, [&](std::size_t i) { return factor * x[i].z(); });
  EXPECT_LT(error, 4e-3);
  const double wrong =
      relative_max_error(*s, [&](std::size_t i) { return std::exp(-0.3) * x[i].z(); });
  EXPECT_GT(wrong, 1e-2);  // the check tells the implicit step from the exact flow
}

TEST(SurfaceStep, ExpansionDilutesAUniformField) {
  // v = a x on the sphere: ∇_M·v = 2a, so with a = 0.5, Δt = 0.1 and no diffusion or
  // reaction φⁿ⁺¹ = φⁿ / (1 + 0.1): φ³ = 1/1.1³. A mis-signed term would give 1/0.9³, a
  // missing one 1. The GFDM divergence of the linear field a x at points of the sphere is
  // 2a to round-off, so only the linear solver's tolerance (relative residual 1e-10) is left.
  auto s = sphere({"0.5 * x", "0.5 * y", "0.5 * z"}, 0.1, MovementOrder::second,
                  advection_diffusion("initial = \"1\"\n"));
  for (int n = 0; n < 3; ++n) s->step();
  const double expected = 1.0 / std::pow(1.1, 3);
  EXPECT_LT(relative_max_error(*s, [&](std::size_t) { return expected; }), 1e-8);
}

}  // namespace
}  // namespace pellicle
