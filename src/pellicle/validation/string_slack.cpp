// String with slack (cases/string_slack.toml; IJNME 1999 §3.2, Figures 15–16; thesis §5.6):
// with the one-way law the mass falls freely until the slack is taken up (about t = 0.013),
// the string pulls until about t = 0.023, and the mass flies back up to its start, reached
// at about t = 0.0375. Each time must agree within 10%; the peak strain energy within 5% of
// the energy the falling mass brings.
#include <cmath>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {

Outcome string_slack(Resolution) {
  auto s = builtin_simulation<2>("string_slack.toml", {"solver.end_time=0.05"});
  const long mass = s->points().bodies[0].end - 1;
  const double y0 = s->points().position[mass].y();
  Series series{"string_slack",
                "String with slack: mass displacement and string energy",
                {"time", "displacement", "strain energy / 100"},
                {}};
  double taut = -1.0, slack = -1.0, apex = -1.0, peak_strain = 0.0;
  double previous_v = 0.0;
  while (!s->finished()) {
    s->step();
    const double t = s->time(), y = s->points().position[mass].y() - y0;
    const double v = s->points().velocity[mass].y();
    const double strain = s->state().strain;
    peak_strain = std::max(peak_strain, strain);
    series.rows.push_back({t, y, strain / 100.0});
    // The string is in tension while it stores energy; 1% of its eventual peak marks it.
    if (taut < 0 && strain > 0.2) taut = t;  // about 1% of the peak (≈ 27)
    if (taut > 0 && slack < 0 && t > taut + 0.002 && strain < 0.2) slack = t;
    if (slack > 0 && apex < 0 && previous_v > 0.0 && v <= 0.0) apex = t;
    previous_v = v;
  }
  Outcome out;
  out.checks.push_back(
      {"slack taken up (string taut)", taut, 0.013, 0.9 * 0.013, 1.1 * 0.013, "s"});
  out.checks.push_back({"string goes slack again", slack, 0.023, 0.9 * 0.023, 1.1 * 0.023, "s"});
  out.checks.push_back(
      {"mass back at the top of its flight", apex, 0.0375, 0.9 * 0.0375, 1.1 * 0.0375, "s"});
  // Energy through the stretch: the mass (3.3, the string's 0.003 aside) falls freely for the
  // measured time to taut, s = ½ g t², then stretches the string, stiffness k = E A / L0
  // (A = thickness 0.1 × unit depth; L0 = 0.3 with five of its nine segments at strain
  // −0.1 of the case, i.e. 10 % longer), until ½ k δ² = m g (s + δ).
  constexpr double kMass = 3.3, kGravity = 250.0, kSegment = 0.3 / 9.0;
  const double rest_length = 4.0 * kSegment + 5.0 * kSegment / 0.9;
  const double k = 1.0e6 * 0.1 / rest_length, weight = kMass * kGravity;
  const double fall = 0.5 * kGravity * taut * taut;
  const double stretch = (weight + std::sqrt(weight * weight + 2.0 * k * weight * fall)) / k;
  const double balance = 0.5 * k * stretch * stretch;
  out.checks.push_back({"peak strain energy against the fall's energy, ½ k δ² = m g (s + δ)",
                        peak_strain, balance, 0.95 * balance, 1.05 * balance, ""});
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
