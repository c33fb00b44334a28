// Contact and topological change of point-cloud surfaces (Suchde & Kuhnert §3.6):
// - joining spheres (§3.7.3, cases/surface_joining_spheres.toml): two unit spheres with
//   centres 2.2 apart approach at relative speed 1. With non-penetration no point may get
//   farther than one step's move plus the near-contact distance, |v| Δt + r_min h, beyond
//   the plane x = 0 where, by symmetry, the two meet (the spheres cannot overlap without
//   crossing it), inside the flattened disc less h; at its rim, where the surfaces fold by
//   up to 90°, no farther than h (a point deeper than h is out of S_i^ext, beyond what
//   contact can see). With delete contact
//   the two become one chamber and enclose the union of two unit spheres whose centres are d = 2.2
//   − t apart, V = 8π/3 − π(4 + d)(2 − d)²/12 (the lens subtracted), at t = 1.5 within what the
//   seam's band (h wide) leaves out; with merge contact they become one chamber at the first step
//   with the gap below r_min h.
// - dumbbell neck pinch (§4.2.3, cases/surface_dumbbell_pinch.toml): under mean-curvature
//   flow the neck of radius 0.2 pinches. An infinite cylinder of radius r0 vanishes at
//   t = r0² = 0.04 (r² = r0² − t with κ the mean of the principal curvatures); the neck,
//   fed by the balls' ends, goes later (the paper's Fig. 14: between t = 0.05 and 0.06). The
//   check: two chambers by t = 0.08 and not before t = 0.04, and the run goes on to t = 0.2
//   with two closed surfaces, the smaller enclosing within 2 % of a unit sphere shrunk by
//   R² = 1 − 2t (the ends' law once apart, the neck a small part of them).
// - torus under averaged flow (§4.2.3, cases/surface_torus_averaged_flow.toml): the hole
//   closes (points reach the axis, contact deletes the inner sides) and the run goes on to
//   t = 10 as one chamber; the time is reported against the paper's t ≈ 7 (Fig. 15).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "pellicle/surface/quadrature.hpp"
#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/surface_support.hpp"

namespace pellicle::validation {

namespace {

//! How far the spheres have crossed the plane x = 0 where, by symmetry, they meet: the
//! largest x of a point of the left sphere (chamber 0) and −x of the right one (chamber 1),
//! over the points within `radius` of the x axis.
double beyond_the_contact_plane(const SurfaceSimulation<3>& s, double radius) {
  const auto& c = s.cloud();
  double beyond = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i)
    if (c.position[i].tail<2>().norm() < radius)
      beyond = std::max(beyond, c.chamber[i] == 0 ? c.position[i].x() : -c.position[i].x());
  return beyond;
}

//! The volume inside two unit spheres whose centres are d apart (0 ≤ d ≤ 2).
double union_of_unit_spheres(double d) {
  const double lens = std::numbers::pi * (4.0 + d) * (2.0 - d) * (2.0 - d) / 12.0;
  return 8.0 * std::numbers::pi / 3.0 - lens;
}

}  // namespace

Outcome surface_joining_spheres(Resolution resolution) {
  Outcome out;
  const double h = resolution == Resolution::full ? 0.1 : 0.2;
  const double r_min = 0.2;  // the case's management.r_min (the default)
  std::vector<double> areas;
  char text[200];
  std::string table = "| response | h | points | result |\n|---|---|---|---|\n";

  {  // non-penetration, to t = 1.8
    auto run = builtin_surface<3>("surface_joining_spheres.toml",
                                  {setting("surface.smoothing_length", h)});
    auto& s = *run.simulation;
    double inside = 0.0, anywhere = 0.0;
    while (!s.finished()) {
      s.step();
      // The flattened disc where the spheres press together: its rim is the circle where a
      // unit sphere whose centre is 1.1 − t/2 from the plane cuts it.
      const double centre = 1.1 - 0.5 * s.time();
      const double rim = centre < 1.0 ? std::sqrt(1.0 - centre * centre) : 0.0;
      inside = std::max(inside, beyond_the_contact_plane(s, rim - h));
      anywhere =
          std::max(anywhere, beyond_the_contact_plane(s, std::numeric_limits<double>::infinity()));
    }
    std::snprintf(text, sizeof text,
                  "| non-penetration | %g | %zu | farthest beyond the contact plane x = 0: %.3g h "
                  "inside the disc's rim less h, %.3g h anywhere (to t = %g) |\n",
                  h, run.initial_points, inside / h, anywhere / h, s.time());
    table += text;
    // Inside the disc a point is projected back at the step it crosses, to ξ beside the other
    // surface as that stood after its own move of |v| Δt (0.5 Δt) within the near distance
    // r_min h of eq 10's fit: (|v| Δt + r_min h) beyond the plane at most. At the rim the two
    // surfaces fold by up to 90° within h, too sharp for eq 10's quadratic; a point deeper
    // than h has left the other part's neighbourhood S_i^ext and cannot be seen at all: h is
    // the method's limit there.
    const double step_move = 0.5 * s.settings().dt;
    std::snprintf(text, sizeof text,
                  "non-penetration, h = %g: farthest beyond the contact plane inside the disc / h",
                  h);
    out.checks.push_back({text, inside / h, 0.0, 0.0, (step_move + r_min * h) / h, ""});
    std::snprintf(text, sizeof text,
                  "non-penetration, h = %g: farthest beyond the contact plane, rim included / h",
                  h);
    out.checks.push_back({text, anywhere / h, 0.0, 0.0, 1.0, ""});
    out.checks.push_back({"non-penetration: chambers at the end",
                          static_cast<double>(s.cloud().chamber_count()), 2.0, 2.0, 2.0, ""});
  }
  {  // delete, to t = 1.5: the union of the spheres
    auto run = builtin_surface<3>("surface_joining_spheres.toml",
                                  {setting("surface.smoothing_length", h),
                                   "surface.contact.between=\"delete\"", "solver.end_time=1.5"});
    auto& s = *run.simulation;
    while (!s.finished()) s.step();
    const double volume = integrate(s.cloud(), s.neighbours(), nullptr, areas).enclosed;
    const double exact = union_of_unit_spheres(2.2 - s.time());
    std::snprintf(text, sizeof text,
                  "| delete | %g | %zu → %zu | %d chamber(s), volume %.4g against the union's "
                  "%.4g (%+.2f %%) at t = %g |\n",
                  h, run.initial_points, s.cloud().size(), s.cloud().chamber_count(), volume, exact,
                  100.0 * (volume / exact - 1.0), s.time());
    table += text;
    out.checks.push_back({"delete: chambers at t = 1.5",
                          static_cast<double>(s.cloud().chamber_count()), 1.0, 1.0, 1.0, ""});
    // The seam: the rims deleted within r_min h of each other stay up to h apart, a band of
    // width h around the circle of radius ρ = √(1 − d²/4) where the spheres meet, whose area
    // the sum (1/3) Σ A_i x_i·n_i leaves out: |ΔV| ≤ 2πρ h · 1/3 (|x·n| ≤ 1 there).
    const double d = 2.2 - s.time();
    const double bound = 2.0 * std::numbers::pi * std::sqrt(1.0 - 0.25 * d * d) * h / 3.0;
    std::snprintf(text, sizeof text, "delete, h = %g: enclosed volume against the union's", h);
    out.checks.push_back({text, 100.0 * (volume / exact - 1.0), 0.0, -100.0 * bound / exact,
                          100.0 * bound / exact, "%"});
  }
  {  // merge: one chamber once they touch (t = 0.2)
    auto run = builtin_surface<3>("surface_joining_spheres.toml",
                                  {setting("surface.smoothing_length", h),
                                   "surface.contact.between=\"merge\"", "solver.end_time=0.6"});
    auto& s = *run.simulation;
    double joined_at = -1.0;
    while (!s.finished() && joined_at < 0.0) {
      s.step();
      if (s.cloud().chamber_count() == 1) joined_at = s.time();
    }
    std::snprintf(text, sizeof text,
                  "| merge | %g | %zu | one chamber at t = %g (touching at 0.2) |\n", h,
                  run.initial_points, joined_at);
    table += text;
    // Merged at the first step with the gap 0.2 − t below the deletion distance r_min h.
    const double dt = s.settings().dt;
    out.checks.push_back({"merge: time the two become one chamber", joined_at, 0.2, 0.2 - r_min * h,
                          0.2 - r_min * h + dt, ""});
  }
  out.table = table;
  return out;
}

Outcome surface_dumbbell_pinch(Resolution resolution) {
  Outcome out;
  const double h = resolution == Resolution::full ? 0.12 : 0.16;
  auto run =
      builtin_surface<3>("surface_dumbbell_pinch.toml", {setting("surface.smoothing_length", h)});
  auto& s = *run.simulation;
  Series series{"dumbbell",
                "Dumbbell under mean-curvature flow: points, chambers and volume",
                {"time", "points", "chambers", "enclosed volume"},
                {}};
  std::vector<double> areas;
  double pinched_at = -1.0;
  while (!s.finished()) {
    s.step();
    const int chambers = s.cloud().chamber_count();
    if (pinched_at < 0.0 && chambers >= 2) pinched_at = s.time();
    series.rows.push_back({s.time(), static_cast<double>(s.cloud().size()),
                           static_cast<double>(chambers),
                           integrate(s.cloud(), s.neighbours(), nullptr, areas).enclosed});
  }
  // Each end a closed surface: the volume each chamber encloses, (1/3) Σ A_i x_i·n_i over
  // its own points, taken about its own centroid.
  const auto& c = s.cloud();
  integrate(c, s.neighbours(), nullptr, areas);
  double smallest = 1e300;
  for (int id : {c.chamber.front(), c.chamber.back()}) {
    Vec3 centroid = Vec3::Zero();
    double count = 0.0, volume = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i)
      if (c.chamber[i] == id) {
        centroid += c.position[i];
        count += 1.0;
      }
    centroid /= count;
    for (std::size_t i = 0; i < c.size(); ++i)
      if (c.chamber[i] == id)
        volume += areas[i] * (c.position[i] - centroid).dot(c.normal(i)) / 3.0;
    smallest = std::min(smallest, volume);
  }
  // Once apart, each end shrinks as a unit sphere under mean-curvature flow does (the neck
  // and the crease are a small part of it): R² = 1 − 2t.
  const double sphere = 4.0 * std::numbers::pi / 3.0 * std::pow(1.0 - 2.0 * s.time(), 1.5);
  char text[300];
  std::snprintf(text, sizeof text,
                "| h | points | neck pinched at | chambers at t = %g | smallest end's volume "
                "(sphere law) |\n|---|---|---|---|---|\n| %g | %zu → %zu | t = %g | %d | %.4g "
                "(%.4g) |\n",
                s.time(), h, run.initial_points, c.size(), pinched_at, c.chamber_count(), smallest,
                sphere);
  out.table = text;
  out.checks.push_back({"time the neck pinches (two chambers)", pinched_at, 0.055, 0.04, 0.08, ""});
  out.checks.push_back(
      {"chambers at t = 0.2", static_cast<double>(c.chamber_count()), 2.0, 2.0, 2.0, ""});
  out.checks.push_back({"smallest end's enclosed volume at t = 0.2 against the sphere law",
                        100.0 * (smallest / sphere - 1.0), 0.0, -2.0, 2.0, "%"});
  out.series.push_back(std::move(series));
  return out;
}

Outcome surface_torus_genus(Resolution resolution) {
  Outcome out;
  (void)resolution;  // the paper's coarse cloud is already fast
  auto run = builtin_surface<3>("surface_torus_averaged_flow.toml", {"output.monitors={}"});
  auto& s = *run.simulation;
  const double h = s.cloud().smoothing_length.front();
  Series series{"torus",
                "Torus under averaged flow: distance of the nearest point from the axis",
                {"time", "nearest to the axis", "points", "enclosed volume"},
                {}};
  std::vector<double> areas;
  const double v0 = integrate(s.cloud(), s.neighbours(), nullptr, areas).enclosed;
  double closed_at = -1.0, largest_change = 0.0;
  while (!s.finished()) {
    s.step();
    double nearest = 1e300;
    for (const Vec3& x : s.cloud().position) nearest = std::min(nearest, std::hypot(x[0], x[1]));
    const double v = integrate(s.cloud(), s.neighbours(), nullptr, areas).enclosed;
    largest_change = std::max(largest_change, std::abs(v / v0 - 1.0));
    // Closed: contact has deleted the inner sides where they met, and points sit on the
    // axis (the surface crosses it: genus 0).
    if (closed_at < 0.0 && s.contact_total().removed > 0 && nearest < 0.25 * h)
      closed_at = s.time();
    series.rows.push_back({s.time(), nearest, static_cast<double>(s.cloud().size()), v});
  }
  char text[240];
  std::snprintf(
      text, sizeof text,
      "| h | points | hole closed at | chambers at t = %g | largest volume change |\n"
      "|---|---|---|---|---|\n| %g | %zu → %zu | t = %g (paper: near 7) | %d | %.2f %% |\n",
      s.time(), h, run.initial_points, s.cloud().size(), closed_at, s.cloud().chamber_count(),
      100.0 * largest_change);
  out.table = text;
  out.checks.push_back({"time the hole closes (genus 1 → 0)", closed_at, 7.0, 0.0, 10.0, ""});
  out.checks.push_back(
      {"chambers at t = 10", static_cast<double>(s.cloud().chamber_count()), 1.0, 1.0, 1.0, ""});
  out.series.push_back(std::move(series));
  return out;
}

}  // namespace pellicle::validation
