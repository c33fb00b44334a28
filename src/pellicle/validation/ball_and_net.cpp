// Ball and net (thesis §5.9 and A.1.6, cases/ball_and_net.toml), run twice: with the net
// Table 11 describes (thickness 0.0125), and with its cross-section the cell width, 0.25,
// the cross-section the thesis's membrane runs have where it can be read (its spring–mass
// problem has A = 0.1, its cell width; its §5.4.4 warns that the membrane force is spread
// over the grid width). The net's own input file is lost.
// Checked with the cell-width net: with contact-release (criterion 9.9) the ball releases
// at about t = 2.8 (within 15%; the release time is when its velocity comes to stay
// within 5% of its final value) and then moves at about −0.7 (within 15%), and leaves at
// least twice as fast as with the single velocity field (thesis: ≈ 0.1); the net stays
// clear of the right wall. With the Table 11 net the ball leaves at least twice as fast as
// with the single field, but the net reaches the wall and throws the ball back: reported.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

struct Run {
  std::vector<std::array<double, 2>> velocity;  // time, ball velocity
  double energy = 0.0;                          // at the end / at the start
  double furthest_net = 0.0;                    // largest x of a net point
  double leaving() const { return velocity.back()[1]; }
  //! When the ball's velocity comes to stay within 5% of its final value.
  double release_time() const {
    double t = 0.0;
    for (const auto& r : velocity)
      if (std::abs(r[1] - leaving()) > 0.05 * std::abs(leaving())) t = r[0];
    return t;
  }
};

Run run(std::vector<std::string> overrides) {
  auto s = builtin_simulation<2>("ball_and_net.toml", overrides);
  const double e0 = s->state().total();
  Run r;
  r.velocity.push_back({0.0, body_velocity(*s, 0).x()});
  const auto& net = s->points().bodies[1];
  while (!s->finished()) {
    s->step();
    r.velocity.push_back({s->time(), body_velocity(*s, 0).x()});
    for (long p = net.begin; p < net.end; ++p)
      r.furthest_net = std::max(r.furthest_net, s->points().position[p].x());
  }
  r.energy = s->state().total() / e0;
  return r;
}

}  // namespace

Outcome ball_and_net(Resolution) {
  Outcome out;
  const std::string single = "contact={model=\"single-field\"}";
  const std::string wide_net =
      "body[1].membrane={shape=\"polyline\", vertices=[[7.5, 0.03125], [7.5, 9.96875]], "
      "points=160, thickness=0.25}";
  const Run table = run({}), table_single = run({single});
  const Run wide = run({wide_net}), wide_single = run({wide_net, single});

  out.checks.push_back({"cell-width net: ball velocity at t = 4.02", wide.leaving(), -0.7,
                        -0.7 * 1.15, -0.7 * 0.85, ""});
  out.checks.push_back(
      {"cell-width net: release time", wide.release_time(), 2.8, 2.8 * 0.85, 2.8 * 1.15, ""});
  out.checks.push_back({"cell-width net: speed with release / with the single field",
                        std::abs(wide.leaving() / wide_single.leaving()), 7.0, 2.0, 1e9, ""});
  out.checks.push_back({"cell-width net: furthest net point (right wall at 10, kernel reach 0.375)",
                        wide.furthest_net, 0.0, 0.0, 10.0 - 0.375, ""});
  out.checks.push_back({"Table 11 net: speed with release / with the single field",
                        std::abs(table.leaving() / table_single.leaving()), 7.0, 2.0, 1e9, ""});
  char text[1024];
  std::snprintf(
      text, sizeof text,
      "| net | contact | ball at t = 4.02 (thesis ≈ −0.7 / ≈ 0.1) | release time (thesis ≈ 2.8) "
      "| energy end / start | furthest net point |\n|---|---|---|---|---|---|\n"
      "| cell width (0.25) | release | %.3f | %.2f | %.3f | %.3f |\n"
      "| cell width (0.25) | single field | %.3f | — | %.3f | %.3f |\n"
      "| Table 11 (0.0125) | release | %.3f | %.2f | %.3f | %.3f |\n"
      "| Table 11 (0.0125) | single field | %.3f | — | %.3f | %.3f |\n",
      wide.leaving(), wide.release_time(), wide.energy, wide.furthest_net, wide_single.leaving(),
      wide_single.energy, wide_single.furthest_net, table.leaving(), table.release_time(),
      table.energy, table.furthest_net, table_single.leaving(), table_single.energy,
      table_single.furthest_net);
  out.table = text;
  Series series{"ball_velocity",
                "Ball and net, cell-width net: ball velocity (compare thesis Figs 42 and 100)",
                {"time", "contact-release", "single field"},
                {}};
  for (std::size_t i = 0; i < wide.velocity.size() && i < wide_single.velocity.size(); i += 50)
    series.rows.push_back({wide.velocity[i][0], wide.velocity[i][1], wide_single.velocity[i][1]});
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
