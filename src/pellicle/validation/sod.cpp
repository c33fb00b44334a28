// Sod's shock tube (thesis §4.1, cases/sod_shock_tube.toml) against the exact Riemann
// solution (riemann.hpp): at t = 0.143 the shock position, the post-shock pressure ratio and
// the shock speed (tracked over the run) within 3%; L1 errors of density, velocity and
// pressure at 100, 200 and 400 cells, each smaller than at the coarser grid and than the
// error of the exact profile displaced by the kernel's support, 3h × its total variation
// (quadratic B-splines with APIC, the case's scheme). At 100 cells also: no artificial viscosity
// (reported), and cell-quadratic densities (thesis eq 4.6) against continuity densities —
// the thesis found them within 0.005; checked within 0.01 away from the contact and shock,
// where the two only smear the jumps differently. The thesis's linear + FLIP scheme is
// reported at every resolution.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/shock_tube.hpp"
#include "pellicle/validation/signals.hpp"

namespace pellicle::validation {
namespace {

constexpr double kGamma = 1.4, kEnd = 0.143;
const ShockTube kSod{{1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, kGamma, kEnd, 1e-4};

//! Largest difference of the mean point density in each cell between two runs, away from
//! the discontinuities (cells within 3 of `skip`), where it measures how the two smear them.
double cell_density_difference(const std::vector<TubeSample>& a, const std::vector<TubeSample>& b,
                               int cells, const std::vector<double>& skip) {
  auto means = [cells](const std::vector<TubeSample>& tube) {
    std::vector<double> sum(cells, 0.0), count(cells, 0.0);
    for (const auto& s : tube) {
      const int c = std::clamp(static_cast<int>(s.x * cells), 0, cells - 1);
      sum[c] += s.rho;
      count[c] += 1.0;
    }
    for (int c = 0; c < cells; ++c) sum[c] = count[c] > 0 ? sum[c] / count[c] : 0.0;
    return sum;
  };
  const auto ma = means(a), mb = means(b);
  double largest = 0.0;
  for (int c = 0; c < cells; ++c) {
    const double x = (c + 0.5) / cells;
    bool near = false;
    for (double jump : skip) near = near || std::abs(x - jump) < 3.0 / cells;
    if (!near) largest = std::max(largest, std::abs(ma[c] - mb[c]));
  }
  return largest;
}

}  // namespace

Outcome sod(Resolution) {
  const ExactRiemann exact(kSod.left, kSod.right, kGamma);
  const double shock_speed = exact.right_shock_speed();
  const double x_shock = 0.5 + shock_speed * kEnd;
  const double x_contact = 0.5 + exact.star_velocity() * kEnd;
  Outcome out;
  char text[256];
  std::string table =
      "| cells | L1 density | L1 velocity | L1 pressure | shock at | shock speed |\n"
      "|---|---|---|---|---|---|\n";
  // Accepted L1 error at a cell h: each wave within the quadratic B-spline's support 3h of
  // its exact place (3h × total variation), and no larger than at the coarser grid.
  const TubeErrors variation = total_variation(exact, kEnd);
  constexpr double inf = std::numeric_limits<double>::infinity();
  TubeErrors previous{inf, inf, inf};
  for (int cells : {100, 200, 400}) {
    const TubeRun run = run_tube(kSod, cells, {}, exact.star_pressure());
    const TubeErrors e = l1_errors(run.tube, exact, kEnd, 1.0 / cells);
    const double front = shock_position(run.tube, exact.star_pressure(), kSod.right.pressure);
    const double speed = slope(run.t, run.front);
    // Post-shock plateau: the middle third between the exact contact and shock.
    const double ratio = plateau_mean(run.tube, x_contact + (x_shock - x_contact) / 3,
                                      x_shock - (x_shock - x_contact) / 3, &TubeSample::p) /
                         kSod.right.pressure;
    const double exact_ratio = exact.star_pressure() / kSod.right.pressure;
    std::snprintf(text, sizeof text, "| %d | %.4g | %.4g | %.4g | %.4f | %.4f |\n", cells,
                  e.density, e.velocity, e.pressure, front, speed);
    table += text;
    const std::string at = ", " + std::to_string(cells) + " cells";
    out.checks.push_back({"shock position" + at, front, x_shock, x_shock - 0.03 * (x_shock - 0.5),
                          x_shock + 0.03 * (x_shock - 0.5), ""});
    out.checks.push_back({"post-shock pressure ratio" + at, ratio, exact_ratio, 0.97 * exact_ratio,
                          1.03 * exact_ratio, ""});
    out.checks.push_back(
        {"shock speed" + at, speed, shock_speed, 0.97 * shock_speed, 1.03 * shock_speed, ""});
    const double support = 3.0 / cells;
    out.checks.push_back({"L1 density error" + at, e.density, 0.0, 0.0,
                          std::min(support * variation.density, previous.density), ""});
    out.checks.push_back({"L1 velocity error" + at, e.velocity, 0.0, 0.0,
                          std::min(support * variation.velocity, previous.velocity), ""});
    out.checks.push_back({"L1 pressure error" + at, e.pressure, 0.0, 0.0,
                          std::min(support * variation.pressure, previous.pressure), ""});
    previous = e;
    if (cells == 100)
      out.series.push_back(tube_profile("profiles_100", "Sod, t = 0.143, 100 cells, c1 = c2 = 1",
                                        run.tube, exact, kEnd, kGamma));
    if (cells == 400)
      out.series.push_back(tube_profile("profiles_400", "Sod, t = 0.143, 400 cells, c1 = c2 = 1",
                                        run.tube, exact, kEnd, kGamma));
  }

  const TubeRun inviscid =
      run_tube(kSod, 100, {"material[0].artificial_viscosity={linear=0.0, quadratic=0.0}"},
               exact.star_pressure());
  const TubeErrors ei = l1_errors(inviscid.tube, exact, kEnd, 0.01);
  std::snprintf(text, sizeof text,
                "| 100, no artificial viscosity | %.4g | %.4g | %.4g | %.4f | |\n", ei.density,
                ei.velocity, ei.pressure,
                shock_position(inviscid.tube, exact.star_pressure(), kSod.right.pressure));
  table += text;
  out.series.push_back(tube_profile("profiles_100_inviscid",
                                    "Sod, t = 0.143, 100 cells, no artificial viscosity",
                                    inviscid.tube, exact, kEnd, kGamma));

  const TubeRun continuity = run_tube(kSod, 100, {}, exact.star_pressure());
  const TubeRun cells =
      run_tube(kSod, 100, {"material[0].density_update=\"cell-quadratic\""}, exact.star_pressure());
  const double difference =
      cell_density_difference(continuity.tube, cells.tube, 100, {x_contact, x_shock});
  const TubeErrors ec = l1_errors(cells.tube, exact, kEnd, 0.01);
  std::snprintf(text, sizeof text,
                "| 100, cell-quadratic density | %.4g | %.4g | %.4g | %.4f | |\n", ec.density,
                ec.velocity, ec.pressure,
                shock_position(cells.tube, exact.star_pressure(), kSod.right.pressure));
  table += text;
  out.checks.push_back({"largest cell-density difference, cell-quadratic vs continuity", difference,
                        0.005, 0.0, 0.01, ""});

  // The thesis's own scheme: linear tent functions with FLIP. Reported, not checked: cell
  // crossing noise in the expansion stops its errors from falling beyond 200 cells.
  for (int cells : {100, 200, 400}) {
    const TubeRun run =
        run_tube(kSod, cells, {"solver.kernel=\"linear\"", "solver.velocity_update=\"flip\""},
                 exact.star_pressure());
    const TubeErrors e = l1_errors(run.tube, exact, kEnd, 1.0 / cells);
    std::snprintf(text, sizeof text,
                  "| %d, linear + FLIP (thesis) | %.4g | %.4g | %.4g | %.4f | %.4f |\n", cells,
                  e.density, e.velocity, e.pressure,
                  shock_position(run.tube, exact.star_pressure(), kSod.right.pressure),
                  slope(run.t, run.front));
    table += text;
    if (cells == 400)
      out.series.push_back(tube_profile("profiles_400_linear_flip",
                                        "Sod, t = 0.143, 400 cells, linear + FLIP (thesis scheme)",
                                        run.tube, exact, kEnd, kGamma));
  }
  out.table = table;
  return out;
}

}  // namespace pellicle::validation
