// Radial vibration of a long solid cylinder, axisymmetric (cases/cylinder_radial_vibration.toml).
// Modal solution: v(r,t) = Σ A_n J1(k_n r) cos(ω_n t) with ξ_n = k_n R the roots of
// ξ J0(ξ) = β J1(ξ), β = (1 − 2ν)/(1 − ν) (traction-free surface, zero axial strain),
// ω_n = c k_n, c = sqrt((λ + 2μ)/ρ), and A_n the projection of the initial v_r = a r on the
// modes, which are orthogonal with weight r. The mass-weighted mean radial velocity of the
// simulation must reverse at the instants the modal series gives.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/signals.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

constexpr double R = 1.0, nu = 0.3, E = 1.0, rho = 1.0, a = 0.01;  // as in the case file

double simpson(const auto& f, double lo, double hi, int n = 2000) {
  const double h = (hi - lo) / n;
  double s = f(lo) + f(hi);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(lo + i * h);
  return s * h / 3.0;
}

struct Mode {
  double omega, weight;  // weight: amplitude in the mean radial velocity
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
    modes.push_back({c * k, A * mean});
  }
  return modes;
}

}  // namespace

Outcome cylinder_radial_vibration(Resolution resolution) {
  const auto modes = radial_modes(16);
  const double period = 2 * std::numbers::pi / modes[0].omega;
  const double cell = resolution == Resolution::full ? 0.0125 : 0.05;
  auto s = builtin_simulation<2>("cylinder_radial_vibration.toml",
                                 {"grid.cell=" + std::to_string(cell)});
  auto exact = [&](double t) {
    double v = 0.0;
    for (const auto& m : modes) v += m.weight * std::cos(m.omega * t);
    return v;
  };
  Series series{"cylinder_velocity",
                "Mean radial velocity of the cylinder",
                {"time", "simulated", "modal solution"},
                {}};
  std::vector<double> t{0.0}, v{body_velocity(*s, 0).x()}, v_exact{exact(0.0)};
  series.rows.push_back({0.0, v[0], v_exact[0]});
  while (!s->finished()) {
    s->step();
    t.push_back(s->time());
    v.push_back(body_velocity(*s, 0).x());
    v_exact.push_back(exact(s->time()));
    series.rows.push_back({t.back(), v.back(), v_exact.back()});
  }
  Outcome out;
  // The mean of v_r = a r over the disk r < R, weighted by r, is 2aR/3.
  out.checks.push_back(
      {"initial mean radial velocity / (2aR/3)", v[0] / (2 * a * R / 3), 1.0, 0.99, 1.01, ""});
  const auto simulated = sign_changes(t, v), expected = sign_changes(t, v_exact);
  double worst = 0.0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const double error = i < simulated.size() ? std::abs(simulated[i] - expected[i]) : period;
    worst = std::max(worst, error);
  }
  char name[160];
  std::snprintf(name, sizeof name,
                "worst reversal-time error over %zu reversals, %d cells (T = %.4f s)",
                expected.size(), static_cast<int>(std::lround(R / cell)), period);
  out.checks.push_back({name, 100 * worst / period, 0.0, 0.0, 1.0, "% of T"});
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
