// Block on an incline with Coulomb friction (cases/friction_block.toml): the acceleration
// of the block's centre of mass along the plate, fitted over t > 0.2 (after the block has
// settled onto the plate), against g (sin θ − μ cos θ) within 3% for μ = 0 and 0.3; for
// μ = 0.7 > tan θ the block must stay put (|a| < 1% of g sin θ).
#include <cmath>
#include <cstdio>
#include <numbers>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/signals.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {

Outcome friction_block(Resolution) {
  constexpr double g = 9.81, theta = std::numbers::pi / 6.0;
  Outcome out;
  Series series{"block_velocity",
                "Block on an incline: velocity along the plate",
                {"time", "mu = 0", "exact mu = 0", "mu = 0.3", "exact mu = 0.3"},
                {}};
  std::vector<std::vector<double>> t(2), v(2);
  for (double mu : {0.0, 0.3, 0.7}) {
    char coefficient[64];
    std::snprintf(coefficient, sizeof coefficient, "contact.coefficient=%g", mu);
    auto s = builtin_simulation<2>("friction_block.toml", {coefficient});
    std::vector<double> time, velocity;
    while (!s->finished()) {
      s->step();
      if (s->time() > 0.2) {
        time.push_back(s->time());
        velocity.push_back(body_velocity(*s, 1).x());
      }
    }
    const double exact = std::max(0.0, g * (std::sin(theta) - mu * std::cos(theta)));
    const double a = slope(time, velocity);
    char name[96];
    std::snprintf(name, sizeof name, "acceleration along the plate, μ = %g", mu);
    if (exact > 0.0)
      out.checks.push_back({name, a, exact, 0.97 * exact, 1.03 * exact, "m/s²"});
    else
      out.checks.push_back(
          {name, a, 0.0, -0.01 * g * std::sin(theta), 0.01 * g * std::sin(theta), "m/s²"});
    if (mu < 0.5) {
      const int k = mu == 0.0 ? 0 : 1;
      t[k] = time;
      v[k] = velocity;
    }
  }
  for (std::size_t i = 0; i < t[0].size() && i < t[1].size(); i += 20) {
    // The exact lines pass through the fitted velocity at t = 0.2 + their slope.
    series.rows.push_back(
        {t[0][i], v[0][i], v[0][0] + g * std::sin(theta) * (t[0][i] - t[0][0]), v[1][i],
         v[1][0] + g * (std::sin(theta) - 0.3 * std::cos(theta)) * (t[1][i] - t[1][0])});
  }
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
