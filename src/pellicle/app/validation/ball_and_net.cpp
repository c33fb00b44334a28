// Ball and net (thesis §5.9 and A.1.6, cases/ball_and_net.toml): with contact-release
// (criterion 9.9) the ball leaves the net much faster than with the single velocity field
// (thesis: about −0.7 against 0.1), checked as at least twice the single field's speed at
// t = 4.02. The thesis's −0.7 itself is reported, not checked: in this reconstruction the
// net reaches the right wall at t ≈ 3.0 and the ball's turn is that bounce (docs/validation). The
// release time (thesis: about 2.8) is reported: from then on the ball's velocity stays within 2% of
// its final value (the contact force never quite vanishes: the net keeps brushing the ball).
#include <cmath>
#include <cstdio>

#include "pellicle/app/validation/problem.hpp"
#include "pellicle/app/validation/support.hpp"

namespace pellicle::validation {

Outcome ball_and_net(Resolution) {
  Outcome out;
  auto s = builtin_simulation<2>("ball_and_net.toml", {});
  const double e0 = s->state().total();
  Series series{"ball_velocity",
                "Ball and net: ball velocity (compare thesis Fig. 100)",
                {"time", "contact-release", "single field"},
                {{0.0, 1.0, 1.0}}};
  while (!s->finished()) {
    s->step();
    series.rows.push_back({s->time(), body_velocity(*s, 0).x(), 0.0});
  }
  const double leaving = body_velocity(*s, 0).x();
  double release = 0.0;
  for (const auto& r : series.rows)
    if (std::abs(r[1] - leaving) > 0.02 * std::abs(leaving)) release = r[0];

  auto stuck = builtin_simulation<2>("ball_and_net.toml", {"contact={model=\"single-field\"}"});
  std::size_t row = 0;
  while (!stuck->finished()) {
    stuck->step();
    if (++row < series.rows.size()) series.rows[row][2] = body_velocity(*stuck, 0).x();
  }
  const double single = body_velocity(*stuck, 0).x();
  out.checks.push_back({"speed with release / speed with the single field at t = 4.02",
                        std::abs(leaving / single), 7.0, 2.0, 1e9, ""});
  char text[320];
  std::snprintf(text, sizeof text,
                "| | contact-release | single field |\n|---|---|---|\n"
                "| ball velocity at t = 4.02 (thesis ≈ −0.7 and ≈ 0.1) | %.3f | %.3f |\n"
                "| energy at t = 4.02 / start | %.3f | %.3f |\n"
                "| release time (thesis ≈ 2.8) | %.3f | — |\n",
                leaving, single, s->state().total() / e0, stuck->state().total() / e0, release);
  out.table = text;
  // Thin the series to every 50th step for the plot.
  Series thin{series.name, series.title, series.columns, {}};
  for (std::size_t i = 0; i < series.rows.size(); i += 50) thin.rows.push_back(series.rows[i]);
  out.series.push_back(std::move(thin));
  return out;
}

}  // namespace pellicle::validation
