// Pendulum (cases/pendulum.toml; IJNME 1999 §3.1.2, thesis §5.7): θ(t), the angle of the line
// from the first to the last point, against the project's explicit bar-element solution
// (bar_chain.hpp) on cells of 0.2, 0.1, 0.05 and 0.025 with 20, 40, 80 and 320 points, as in
// the seeds. The error over 1.5 swings must fall with every refinement and stay below the
// turn of the line that an end point misplaced by one cell gives, atan(h/L).
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "pellicle/validation/bar_chain.hpp"
#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

constexpr double kLength = 0.73, kTheta0 = 19.8 * std::numbers::pi / 180.0;
const Vec2 kPivot(0.5, 0.9999);
const Vec2 kEnd = kPivot + kLength * Vec2(-std::sin(kTheta0), -std::cos(kTheta0));

double angle_degrees(const Vec2& pivot, const Vec2& end) {
  const Vec2 d = end - pivot;
  return std::atan2(-d.x(), -d.y()) * -180.0 / std::numbers::pi;  // from −y, counter-clockwise
}

struct Swing {
  std::vector<double> t, theta;
};

Swing reference(int elements, double end_time) {
  BarChainSettings s;
  s.pivot = kPivot;
  s.end = kEnd;
  s.elements = elements;
  s.youngs_modulus = 1.0e6;
  s.area = 0.01;  // thickness × unit depth
  s.density = 1.0;
  s.end_mass = 3.3;
  s.gravity = Vec2(0.0, -20.0);
  s.one_way = true;
  s.end_time = end_time;
  Swing out;
  for (const auto& sample : solve_bar_chain(s)) {
    out.t.push_back(sample.time);
    out.theta.push_back(angle_degrees(kPivot, sample.end));
  }
  return out;
}

double interpolate(const Swing& s, double t) {
  const auto it = std::lower_bound(s.t.begin(), s.t.end(), t);
  if (it == s.t.begin()) return s.theta.front();
  if (it == s.t.end()) return s.theta.back();
  const std::size_t j = it - s.t.begin();
  const double f = (t - s.t[j - 1]) / (s.t[j] - s.t[j - 1]);
  return s.theta[j - 1] + f * (s.theta[j] - s.theta[j - 1]);
}

Swing simulate(double cell, int points, const std::vector<std::string>& extra,
               const std::string& frames = "connectivity") {
  std::vector<std::string> overrides = {
      "grid.cell=" + std::to_string(cell),
      "body[0].membrane={shape=\"polyline\", vertices=[[0.5, 0.9999], [" +
          std::to_string(kEnd.x()) + ", " + std::to_string(kEnd.y()) +
          "]], points=" + std::to_string(points) + ", thickness=0.01, frames=\"" + frames + "\"}",
      "body[0].point_masses=[[" + std::to_string(points - 1) + ", 3.3]]"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  auto s = builtin_simulation<2>("pendulum.toml", overrides);
  const auto& p = s->points();
  const long last = p.bodies[0].end - 1, first = p.bodies[0].begin;
  Swing out{{0.0}, {angle_degrees(p.position[first], p.position[last])}};
  while (!s->finished()) {
    s->step();
    out.t.push_back(s->time());
    out.theta.push_back(angle_degrees(p.position[first], p.position[last]));
  }
  return out;
}

}  // namespace

Outcome pendulum(Resolution resolution) {
  constexpr double kEndTime = 1.75;
  const Swing fe = reference(200, kEndTime), fe_fine = reference(400, kEndTime);
  Outcome out;
  double fe_change = 0.0;
  for (std::size_t i = 0; i < fe.t.size(); ++i)
    fe_change = std::max(fe_change, std::abs(fe.theta[i] - interpolate(fe_fine, fe.t[i])));
  out.checks.push_back(
      {"bar-element reference: 200 vs 400 elements, max |Δθ|", fe_change, 0.0, 0.0, 0.05, "deg"});
  Series series{"pendulum_theta",
                "Pendulum angle θ(t) in degrees: MPM and bar elements",
                {"time", "bar elements"},
                {}};
  // The seeds' kernel with a 1% PIC share, and APIC with quadratic B-splines. (Pure FLIP
  // lets the light string points ring until the string breaks on the finer grids.)
  const struct {
    const char* label;
    std::vector<std::string> settings;
  } variants[] = {
      {"linear + FLIP/PIC 0.99",
       {"solver.velocity_update=blend", "solver.flip_fraction=0.99", "solver.kernel=linear"}},
      {"quadratic B-spline + APIC",
       {"solver.velocity_update=apic", "solver.kernel=quadratic-bspline"}},
  };
  const double cells[] = {0.2, 0.1, 0.05, 0.025};
  const int counts[] = {20, 40, 80, 320};
  const int grids = resolution == Resolution::full ? 4 : 3;
  std::vector<Swing> runs;
  for (const auto& variant : variants) {
    double previous = std::numeric_limits<double>::infinity();
    for (int r = 0; r < grids; ++r) {
      runs.push_back(simulate(cells[r], counts[r], variant.settings));
      const Swing& run = runs.back();
      double error = 0.0;
      for (std::size_t i = 0; i < run.t.size(); ++i)
        error = std::max(error, std::abs(run.theta[i] - interpolate(fe, run.t[i])));
      char name[160];
      std::snprintf(name, sizeof name, "%s, cell %.3g, %d points: max |θ − θ_FE|", variant.label,
                    cells[r], counts[r]);
      // The end point placed within one cell of its place on the string of length L turns
      // the line by at most atan(h/L); each refinement must reduce the error (IJNME:
      // convergence toward the FE solution).
      const double one_cell = std::atan(cells[r] / kLength) * 180.0 / std::numbers::pi;
      out.checks.push_back({name, error, 0.0, 0.0, std::min(previous, one_cell), "deg"});
      previous = error;
      char column[96];  // CSV header: no commas
      std::snprintf(column, sizeof column, "%s h=%g", variant.label, cells[r]);
      series.columns.push_back(column);
    }
    // Numerical dissipation: the swing back, against the bar elements' (IJNME Fig. 12).
    const Swing& finest = runs.back();
    double mpm = 0.0, ref = 0.0;
    for (std::size_t i = 0; i < finest.t.size(); ++i)
      if (finest.t[i] > 0.9) mpm = std::min(mpm, finest.theta[i]);
    for (std::size_t i = 0; i < fe.t.size(); ++i)
      if (fe.t[i] > 0.9) ref = std::min(ref, fe.theta[i]);
    out.checks.push_back(
        {std::string(variant.label) + ", finest grid: second swing amplitude / FE's", mpm / ref,
         1.0, 0.9, 1.02, ""});
  }
  for (double t = 0.0; t <= kEndTime; t += 0.005) {
    std::vector<double> row{t, interpolate(fe, t)};
    for (const auto& run : runs) row.push_back(interpolate(run, t));
    series.rows.push_back(row);
  }
  // The same swing with frames from the points alone (no connectivity): the local
  // isosurface method, hybrid rule (Sulsky & York 2000 §8), at cell 0.1 with 40 points.
  const Swing with_order = simulate(0.1, 40, variants[1].settings);
  const Swing without = simulate(0.1, 40, variants[1].settings, "isosurface-hybrid");
  double difference = 0.0;
  for (std::size_t i = 0; i < without.t.size(); ++i)
    difference =
        std::max(difference, std::abs(without.theta[i] - interpolate(with_order, without.t[i])));
  out.checks.push_back({"cell 0.1: max |θ(isosurface-hybrid frames) − θ(connectivity frames)|",
                        difference, 0.0, 0.0, 2.0, "deg"});
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
