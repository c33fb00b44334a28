// Axisymmetric kinematics and dynamics.
// 1. Point volumes carry 2πr: a filled cylinder has the mass ρπR²H.
// 2. Radial vibration of a solid cylinder (cases/cylinder_radial_vibration.toml) against the
//    modal solution: v(r,t) = Σ A_n J1(k_n r) cos(ω_n t), ξ_n = k_n R the roots of
//    ξ J0(ξ) = β J1(ξ), β = (1 − 2ν)/(1 − ν), ω_n = c k_n, A_n the projection of v_r = a r
//    onto the modes (orthogonal with weight r). The mean radial velocity must reverse at the
//    analytic instants within 1% of the fundamental period.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "support/case_text.hpp"

namespace pellicle {
namespace {

constexpr double R = 1.0, nu = 0.3, E = 1.0, rho = 1.0, a = 0.01;

double simpson(const auto& f, double lo, double hi, int n = 2000) {
  const double h = (hi - lo) / n;
  double s = f(lo) + f(hi);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(lo + i * h);
  return s * h / 3.0;
}

struct Mode {
  double k, omega, weight;  // weight: contribution to the mean radial velocity
};

std::vector<Mode> radial_modes(int count) {
  const double beta = (1 - 2 * nu) / (1 - nu);
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double c = std::sqrt((lambda + 2 * mu) / rho);
  auto f = [&](double x) { return x * std::cyl_bessel_j(0, x) - beta * std::cyl_bessel_j(1, x); };
  std::vector<Mode> modes;
  for (double x = 0.05; static_cast<int>(modes.size()) < count; x += 0.05) {
    if (f(x) * f(x + 0.05) > 0) continue;
    double lo = x, hi = x + 0.05;
    for (int i = 0; i < 60; ++i) ((f(lo) * f(0.5 * (lo + hi)) <= 0) ? hi : lo) = 0.5 * (lo + hi);
    const double k = 0.5 * (lo + hi) / R;
    const auto J1 = [&](double r) { return std::cyl_bessel_j(1, k * r); };
    const double A = simpson([&](double r) { return a * r * J1(r) * r; }, 0, R) /
                     simpson([&](double r) { return J1(r) * J1(r) * r; }, 0, R);
    const double mean = simpson([&](double r) { return J1(r) * r; }, 0, R) / (R * R / 2);
    modes.push_back({k, c * k, A * mean});
  }
  return modes;
}

TEST(Axisymmetric, PointVolumesCarryTwoPiR) {
  auto s = testing::simulation_from_text<2>(testing::case_file("cylinder_radial_vibration.toml"));
  double mass = 0.0;
  for (double m : s->points().mass) mass += m;
  EXPECT_NEAR(mass, rho * std::numbers::pi * R * R * 0.2, 1e-12);
}

TEST(Axisymmetric, RadialVibrationMatchesModalSolution) {
  const auto modes = radial_modes(12);
  const double period = 2 * std::numbers::pi / modes[0].omega;

  auto s = testing::simulation_from_text<2>(testing::case_file("cylinder_radial_vibration.toml"));
  std::vector<double> t{0.0}, v{testing::body_velocity(*s, 0).x()}, v_exact{};
  while (!s->finished()) {
    s->step();
    t.push_back(s->time());
    v.push_back(testing::body_velocity(*s, 0).x());
  }
  for (double ti : t) {
    double sum = 0.0;
    for (const auto& m : modes) sum += m.weight * std::cos(m.omega * ti);
    v_exact.push_back(sum);
  }
  // The initial mean radial velocity is 2aR/3 both in the model and the simulation.
  EXPECT_NEAR(v_exact[0], 2 * a * R / 3, 2e-4 * a);
  EXPECT_NEAR(v[0], 2 * a * R / 3, 0.02 * a);
  const auto simulated = testing::sign_changes(t, v), exact = testing::sign_changes(t, v_exact);
  ASSERT_GE(exact.size(), 4u);
  ASSERT_GE(simulated.size(), exact.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    EXPECT_NEAR(simulated[i], exact[i], 0.01 * period) << "reversal " << i;
    worst = std::max(worst, std::abs(simulated[i] - exact[i]) / period);
  }
  RecordProperty("worst_reversal_error_in_periods", std::to_string(worst));
  std::printf("radial vibration: %zu reversals, worst error %.3f%% of T = %.4f\n", exact.size(),
              100 * worst, period);
}

}  // namespace
}  // namespace pellicle
