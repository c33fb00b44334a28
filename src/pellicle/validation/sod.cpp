// Sod's shock tube (thesis §4.1, cases/sod_shock_tube.toml) against the exact Riemann
// solution (riemann.hpp): at t = 0.143 the shock position, the post-shock pressure ratio and
// the shock speed (tracked over the run) within 3%; L1 errors of density, velocity and
// pressure at 100, 200 and 400 cells, each smaller than at the coarser grid (quadratic
// B-splines with APIC, the case's scheme). At 100 cells also: no artificial viscosity
// (reported), and cell-quadratic densities (thesis eq 4.6) against continuity densities —
// the thesis found them within 0.005; checked within 0.01 away from the contact and shock,
// where the two only smear the jumps differently. The thesis's linear + FLIP scheme is
// reported at every resolution.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/riemann.hpp"
#include "pellicle/validation/signals.hpp"
#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

constexpr double kGamma = 1.4, kEnd = 0.143;
const GasState kLeft{1.0, 0.0, 1.0}, kRight{0.125, 0.0, 0.1};

//! One point of the tube at the end: position, density, velocity, pressure, energy, volume.
struct Sample {
  double x, rho, u, p, e, volume;
};

std::vector<Sample> samples(const Simulation<2>& s) {
  const auto& pts = s.points();
  const auto& energy = pts.named<double>("internal_energy");
  std::vector<Sample> out;
  for (long i = 0; i < pts.size(); ++i)
    out.push_back({pts.position[i].x(), pts.density[i], pts.velocity[i].x(),
                   (kGamma - 1.0) * pts.density[i] * energy[i], energy[i], pts.volume[i]});
  std::sort(out.begin(), out.end(), [](const Sample& a, const Sample& b) { return a.x < b.x; });
  return out;
}

//! Rightmost point whose pressure is above the mid-shock value: the shock front.
double shock_position(const std::vector<Sample>& tube, double p_star) {
  const double middle = 0.5 * (p_star + kRight.pressure);
  double front = 0.0;
  for (const auto& s : tube)
    if (s.p > middle) front = s.x;
  return front;
}

struct Run {
  std::vector<Sample> tube;
  std::vector<double> t, front;  //!< shock-front history
};

Run run_tube(int cells, const std::vector<std::string>& extra, double p_star) {
  const double h = 1.0 / cells;
  char cell[64], upper[64], dt[64], high[160], low[160];
  std::snprintf(cell, sizeof cell, "grid.cell=%.12g", h);
  std::snprintf(upper, sizeof upper, "grid.upper=[1.0, %.12g]", h);
  std::snprintf(dt, sizeof dt, "solver.dt=%.12g", 1e-4 * 100.0 / cells);
  std::snprintf(high, sizeof high,
                "body[0].region={shape=\"box\", lower=[0.0, 0.0], upper=[0.5, %.12g]}", h);
  std::snprintf(low, sizeof low,
                "body[1].region={shape=\"box\", lower=[0.5, 0.0], upper=[1.0, %.12g]}", h);
  std::vector<std::string> overrides{cell, upper, dt, high, low};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  auto s = builtin_simulation<2>("sod_shock_tube.toml", overrides);
  Run run;
  long step = 0;
  while (!s->finished()) {
    s->step();
    if (++step % 10 == 0 && s->time() > 0.03) {
      run.t.push_back(s->time());
      run.front.push_back(shock_position(samples(*s), p_star));
    }
  }
  run.tube = samples(*s);
  return run;
}

struct Errors {
  double density = 0.0, velocity = 0.0, pressure = 0.0;
};

//! L1 norms ∫|f − f_exact| dx over the tube, each point standing for its length V/height.
Errors l1_errors(const std::vector<Sample>& tube, const ExactRiemann& exact, double height) {
  Errors e;
  for (const auto& s : tube) {
    const GasState g = exact.sample((s.x - 0.5) / kEnd);
    const double dx = s.volume / height;
    e.density += dx * std::abs(s.rho - g.density);
    e.velocity += dx * std::abs(s.u - g.velocity);
    e.pressure += dx * std::abs(s.p - g.pressure);
  }
  return e;
}

Series profile(const std::string& name, const std::string& title, const std::vector<Sample>& tube,
               const ExactRiemann& exact) {
  Series out{name,
             title,
             {"x", "density", "exact density", "velocity", "exact velocity", "pressure",
              "exact pressure", "internal energy", "exact internal energy"},
             {}};
  double last_x = -1.0;
  for (const auto& s : tube) {
    if (s.x == last_x) continue;  // the points across the tube repeat the same values
    last_x = s.x;
    const GasState g = exact.sample((s.x - 0.5) / kEnd);
    out.rows.push_back({s.x, s.rho, g.density, s.u, g.velocity, s.p, g.pressure, s.e,
                        g.pressure / ((kGamma - 1.0) * g.density)});
  }
  return out;
}

//! Largest difference of the mean point density in each cell between two runs, away from
//! the discontinuities (cells within 3 of `skip`), where it measures how the two smear them.
double cell_density_difference(const std::vector<Sample>& a, const std::vector<Sample>& b,
                               int cells, const std::vector<double>& skip) {
  auto means = [cells](const std::vector<Sample>& tube) {
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
  const ExactRiemann exact(kLeft, kRight, kGamma);
  const double shock_speed = exact.right_shock_speed();
  const double x_shock = 0.5 + shock_speed * kEnd;
  const double x_contact = 0.5 + exact.star_velocity() * kEnd;
  Outcome out;
  char text[256];
  std::string table =
      "| cells | L1 density | L1 velocity | L1 pressure | shock at | shock speed |\n"
      "|---|---|---|---|---|---|\n";
  Errors previous{1e9, 1e9, 1e9};
  for (int cells : {100, 200, 400}) {
    const Run run = run_tube(cells, {}, exact.star_pressure());
    const Errors e = l1_errors(run.tube, exact, 1.0 / cells);
    const double front = shock_position(run.tube, exact.star_pressure());
    const double speed = slope(run.t, run.front);
    // Post-shock plateau: the middle third between the exact contact and shock.
    double sum = 0.0, n = 0.0;
    for (const auto& s : run.tube)
      if (s.x > x_contact + (x_shock - x_contact) / 3 && s.x < x_shock - (x_shock - x_contact) / 3)
        sum += s.p, n += 1.0;
    const double ratio = sum / n / kRight.pressure;
    const double exact_ratio = exact.star_pressure() / kRight.pressure;
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
    out.checks.push_back({"L1 density error" + at, e.density, 0.0, 0.0, previous.density, ""});
    out.checks.push_back({"L1 velocity error" + at, e.velocity, 0.0, 0.0, previous.velocity, ""});
    out.checks.push_back({"L1 pressure error" + at, e.pressure, 0.0, 0.0, previous.pressure, ""});
    previous = e;
    if (cells == 100)
      out.series.push_back(
          profile("profiles_100", "Sod, t = 0.143, 100 cells, c1 = c2 = 1", run.tube, exact));
    if (cells == 400)
      out.series.push_back(
          profile("profiles_400", "Sod, t = 0.143, 400 cells, c1 = c2 = 1", run.tube, exact));
  }

  const Run inviscid = run_tube(
      100, {"material[0].artificial_viscosity={linear=0.0, quadratic=0.0}"}, exact.star_pressure());
  const Errors ei = l1_errors(inviscid.tube, exact, 0.01);
  std::snprintf(text, sizeof text,
                "| 100, no artificial viscosity | %.4g | %.4g | %.4g | %.4f | |\n", ei.density,
                ei.velocity, ei.pressure, shock_position(inviscid.tube, exact.star_pressure()));
  table += text;
  out.series.push_back(profile("profiles_100_inviscid",
                               "Sod, t = 0.143, 100 cells, no artificial viscosity", inviscid.tube,
                               exact));

  const Run continuity = run_tube(100, {}, exact.star_pressure());
  const Run cells =
      run_tube(100, {"material[0].density_update=\"cell-quadratic\""}, exact.star_pressure());
  const double difference =
      cell_density_difference(continuity.tube, cells.tube, 100, {x_contact, x_shock});
  const Errors ec = l1_errors(cells.tube, exact, 0.01);
  std::snprintf(text, sizeof text,
                "| 100, cell-quadratic density | %.4g | %.4g | %.4g | %.4f | |\n", ec.density,
                ec.velocity, ec.pressure, shock_position(cells.tube, exact.star_pressure()));
  table += text;
  out.checks.push_back({"largest cell-density difference, cell-quadratic vs continuity", difference,
                        0.005, 0.0, 0.01, ""});

  // The thesis's own scheme: linear tent functions with FLIP. Reported, not checked: cell
  // crossing noise in the expansion stops its errors from falling beyond 200 cells.
  for (int cells : {100, 200, 400}) {
    const Run run = run_tube(cells, {"solver.kernel=\"linear\"", "solver.velocity_update=\"flip\""},
                             exact.star_pressure());
    const Errors e = l1_errors(run.tube, exact, 1.0 / cells);
    std::snprintf(text, sizeof text,
                  "| %d, linear + FLIP (thesis) | %.4g | %.4g | %.4g | %.4f | %.4f |\n", cells,
                  e.density, e.velocity, e.pressure,
                  shock_position(run.tube, exact.star_pressure()), slope(run.t, run.front));
    table += text;
    if (cells == 400)
      out.series.push_back(profile("profiles_400_linear_flip",
                                   "Sod, t = 0.143, 400 cells, linear + FLIP (thesis scheme)",
                                   run.tube, exact));
  }
  out.table = table;
  return out;
}

}  // namespace pellicle::validation
