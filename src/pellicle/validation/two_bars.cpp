// Two-bar impact with the single (centre-of-mass) velocity field, IJNME 1999 §4.1 and the
// thesis's deck A.4.12 (cases/two_bars_stick.toml). Figure 18: the bars do not separate; they
// move on together at about the shared velocity 1 with oscillating velocities (an elastic
// release would leave about 0.3 and 1.7, §4.2), apart from a spell near t = 0.35–0.425 when
// they are one cell apart.
#include <algorithm>
#include <cmath>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {

Outcome two_bars_stick(Resolution) {
  auto s = builtin_simulation<2>("two_bars_stick.toml", {});
  const auto& p = s->points();
  const double momentum0 = s->state().momentum.x();
  Series series{"two_bars_velocity",
                "Centre-of-mass velocities (compare IJNME Fig. 18b)",
                {"time", "left bar", "right bar"},
                {{0.0, 2.0, 0.0}}};
  double left_sum = 0.0, right_sum = 0.0, momentum_error = 0.0;
  int samples = 0;
  while (!s->finished()) {
    s->step();
    const double left = body_velocity(*s, 0).x(), right = body_velocity(*s, 1).x();
    series.rows.push_back({s->time(), left, right});
    momentum_error = std::max(momentum_error, std::abs(s->state().momentum.x() / momentum0 - 1));
    if (s->time() >= 0.45) {  // after the last separation spell of Figure 18
      left_sum += left;
      right_sum += right;
      ++samples;
    }
  }
  double left_edge = -1e9, right_edge = 1e9;
  for (long i = p.bodies[0].begin; i < p.bodies[0].end; ++i)
    left_edge = std::max(left_edge, p.position[i].x());
  for (long i = p.bodies[1].begin; i < p.bodies[1].end; ++i)
    right_edge = std::min(right_edge, p.position[i].x());
  const double h = s->grid().cell();
  Outcome out;
  out.checks.push_back(
      {"mean left-bar velocity, t ≥ 0.45", left_sum / samples, 1.0, 0.85, 1.15, ""});
  out.checks.push_back(
      {"mean right-bar velocity, t ≥ 0.45", right_sum / samples, 1.0, 0.85, 1.15, ""});
  // Contact in the paper's sense: facing points in the same or neighbouring cells, so both
  // bars contribute to a shared line of grid nodes.
  out.checks.push_back({"cells between the facing points at t = 0.501",
                        std::floor(right_edge / h) - std::floor(left_edge / h), 1.0, 0.0, 1.0, ""});
  out.checks.push_back({"relative change of total momentum", momentum_error, 0.0, 0.0, 1e-9, ""});
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
