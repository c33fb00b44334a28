// Lagrangian movement of point clouds (Suchde & Kuhnert §3.7.1–3.7.2).
//
// Rotating quarter sphere (cases/surface_rotating_quarter_sphere.toml, eq 11): the mean
// distance |‖x‖ − 1| from the unit sphere after one rotation (89 steps of 0.05). The paper:
// 1.37e-1 with the first-order movement (eq 2), 5.57e-4 with the second-order one (eq 3),
// 1.12e-4 after the first step. Checked: first order within a factor 1.5 of the paper's;
// second order at least 50 times smaller than first order; second order adding less than
// a third of its first-step error over the remaining 88 steps. The paper's 1.12e-4 after
// one step cannot be had from eq 2 at Δt = 0.05 (one Euler step leaves ½|ω × x|²Δt², which
// averages 1.4e-3 to 1.7e-3 on a quarter sphere with |ω| = √2), and that first step dominates
// the second-order error after a rotation, so the paper's 5.57e-4 is reported, not checked.
//
// Deforming hemisphere (cases/surface_deforming_hemisphere.toml, eqs 12–13): stretched and
// returned to its shape at t = 0.5 and 1 with point management. The paper finds the eq 13
// error there first order in Δt (Figure 8) and blames the first step, which must be eq 2.
// Here it converges at about second order: the velocity of eq 12 has no material
// acceleration at t = 0 (∂v/∂t = 0 and v · ∇v = 0 there), so the first Euler step is exact
// to O(Δt³) and eq 3 keeps second order. Checked: at least first order (≥ 0.8) at both times,
// down to Δt = 0.0025. Below that (--full adds 0.00125, reported only) the error meets the
// floor the point management leaves: the points added while the surface stretches sit off
// it by their placement error (about 1e-6 here), which no smaller Δt removes.
#include <cmath>
#include <cstdio>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/surface_support.hpp"

namespace pellicle::validation {

namespace {

double mean_distance(const PointCloud<3>& c) {
  double sum = 0.0;
  for (const auto& x : c.position) sum += std::abs(x.norm() - 1.0);
  return sum / c.size();
}

//! eq 13: (1/N) Σ |‖x‖² − 1|.
double sphere_error(const PointCloud<3>& c) {
  double sum = 0.0;
  for (const auto& x : c.position) sum += std::abs(x.squaredNorm() - 1.0);
  return sum / c.size();
}

void rotating_quarter_sphere(Outcome& out) {
  double after_one[2] = {0, 0}, after_all[2] = {0, 0};
  std::size_t points = 0;
  Series series{"quarter_sphere_distance",
                "Rotating quarter sphere: mean distance from the unit sphere",
                {"time", "first order (eq 2)", "second order (eq 3)"},
                {}};
  for (int order = 0; order < 2; ++order) {
    auto run = builtin_surface<3>(
        "surface_rotating_quarter_sphere.toml",
        {order == 0 ? "surface.movement=first-order" : "surface.movement=second-order",
         "output.monitors={}"});
    auto& s = *run.simulation;
    points = run.initial_points;
    int step = 0;
    while (!s.finished()) {
      s.step();
      if (++step == 1) after_one[order] = mean_distance(s.cloud());
      if (order == 0)
        series.rows.push_back({s.time(), mean_distance(s.cloud()), 0.0});
      else
        series.rows[step - 1][2] = mean_distance(s.cloud());
    }
    after_all[order] = mean_distance(s.cloud());
  }
  char line[512];
  std::snprintf(line, sizeof line,
                "\nRotating quarter sphere, %zu points, Δt = 0.05, one rotation: mean distance "
                "from the sphere\n\n| movement | after 1 step | after 89 steps | paper (1 step / "
                "rotation) |\n|---|---|---|---|\n| first order (eq 2) | %.3g | %.3g | 1.12e-4 / "
                "1.37e-1 |\n| second order (eq 3) | %.3g | %.3g | 1.12e-4 / 5.57e-4 |\n",
                points, after_one[0], after_all[0], after_one[1], after_all[1]);
  out.table += line;
  out.checks.push_back(
      {"quarter sphere, first-order movement: distance after one rotation / "
       "paper's 1.37e-1",
       after_all[0] / 1.37e-1, 1.0, 1.0 / 1.5, 1.5, ""});
  out.checks.push_back({"quarter sphere: second-order / first-order distance after one rotation",
                        after_all[1] / after_all[0], 5.57e-4 / 1.37e-1, 0.0, 0.02, ""});
  out.checks.push_back(
      {"quarter sphere, second order: growth after the first step / first-step "
       "distance",
       after_all[1] / after_one[1] - 1.0, 0.0, 0.0, 1.0 / 3.0, ""});
  out.series.push_back(std::move(series));
}

void deforming_hemisphere(Outcome& out, bool full) {
  std::vector<double> steps = {0.01, 0.005};
  if (full) steps.insert(steps.end(), {0.0025, 0.00125});
  std::vector<double> at_half, at_one;
  Series points{
      "hemisphere_points", "Deforming hemisphere: number of points N(t)", {"time", "N"}, {}};
  out.table +=
      "\nDeforming hemisphere, eq 13 error when the shape returns\n\n| Δt | t = 0.5 | "
      "t = 1 | points at t = 0 / 0.25 / 1 |\n|---|---|---|---|\n";
  for (double dt : steps) {
    auto run = builtin_surface<3>("surface_deforming_hemisphere.toml",
                                  {setting("solver.dt", dt), "output.monitors={}"});
    auto& s = *run.simulation;
    std::size_t quarter = 0;
    while (!s.finished()) {
      s.step();
      if (std::abs(s.time() - 0.5) < 0.5 * dt) at_half.push_back(sphere_error(s.cloud()));
      if (std::abs(s.time() - 0.25) < 0.5 * dt) quarter = s.cloud().size();
      if (dt == steps[1]) points.rows.push_back({s.time(), double(s.cloud().size())});
    }
    at_one.push_back(sphere_error(s.cloud()));
    char line[256];
    std::snprintf(line, sizeof line, "| %g | %.3g | %.3g | %zu / %zu / %zu |\n", dt, at_half.back(),
                  at_one.back(), run.initial_points, quarter, s.cloud().size());
    out.table += line;
  }
  const std::size_t checked = std::min<std::size_t>(steps.size(), 3);
  for (std::size_t k = 1; k < checked; ++k) {
    char name[128];
    std::snprintf(name, sizeof name, "hemisphere, order in Δt at t = 0.5, Δt = %g", steps[k]);
    out.checks.push_back(
        {name, order(at_half[k - 1], at_half[k], steps[k - 1], steps[k]), 1.0, 0.8, 3.0, ""});
    std::snprintf(name, sizeof name, "hemisphere, order in Δt at t = 1, Δt = %g", steps[k]);
    out.checks.push_back(
        {name, order(at_one[k - 1], at_one[k], steps[k - 1], steps[k]), 1.0, 0.8, 3.0, ""});
  }
  out.series.push_back(std::move(points));
}

}  // namespace

Outcome surface_movement(Resolution resolution) {
  Outcome out;
  rotating_quarter_sphere(out);
  deforming_hemisphere(out, resolution == Resolution::full);
  return out;
}

}  // namespace pellicle::validation
