#include "pellicle/validation/bar_chain.hpp"

#include <cmath>

namespace pellicle::validation {

std::vector<BarChainSample> solve_bar_chain(const BarChainSettings& s) {
  const int n = s.elements;
  const double l0 = (s.end - s.pivot).norm() / n;
  std::vector<Vec2> x(n + 1), v(n + 1, Vec2::Zero()), f(n + 1);
  std::vector<double> mass(n + 1, 0.0);
  for (int i = 0; i <= n; ++i) x[i] = s.pivot + (s.end - s.pivot) * (double(i) / n);
  for (int e = 0; e < n; ++e) {  // lumped: half of each bar's mass to either node
    mass[e] += 0.5 * s.density * s.area * l0;
    mass[e + 1] += 0.5 * s.density * s.area * l0;
  }
  mass[n] += s.end_mass;
  const double dt = s.courant * l0 / std::sqrt(s.youngs_modulus / s.density);
  std::vector<BarChainSample> out{{0.0, x[n]}};
  double t = 0.0, next_sample = s.sample_interval;
  bool first = true;
  while (t < s.end_time - 1e-12) {
    for (int i = 0; i <= n; ++i) f[i] = mass[i] * s.gravity;
    for (int e = 0; e < n; ++e) {
      const Vec2 d = x[e + 1] - x[e];
      const double l = d.norm();
      double tension = s.youngs_modulus * s.area * (l - l0) / l0;
      if (s.one_way && tension < 0.0) tension = 0.0;
      f[e] += tension * d / l;
      f[e + 1] -= tension * d / l;
    }
    // Central differences: v at half steps (a half step at the start), x at full steps.
    const double h = first ? 0.5 * dt : dt;
    first = false;
    for (int i = 1; i <= n; ++i) {  // node 0 is pinned
      v[i] += h * f[i] / mass[i];
      x[i] += dt * v[i];
    }
    t += dt;
    if (t >= next_sample - 1e-12) {
      out.push_back({t, x[n]});
      next_sample += s.sample_interval;
    }
  }
  return out;
}

}  // namespace pellicle::validation
