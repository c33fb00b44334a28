// Diffusion on a deforming half pipe (Suchde & Kuhnert §4.2.2, eq 35;
// cases/surface_half_pipe.toml): φ diffuses with zero flux through the boundary while the
// surface swells with φ and twists, so ∫ φ dA is constant (docs/theory/surface-pdes.md). The
// paper shows pictures only (Figure 13, lost), so the check is the conservation: the largest
// relative change of Σ_i A_i φ_i (the one-ring quadrature of history.csv's total_phi) over
// t ∈ [0, 2] within 1 %, and, with --full, that change falling with h (order ≥ 1 from
// h = 0.1 to 0.05). The GFDM rows are not conservative by construction; the change is their
// consistency error, and the quadrature's.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pellicle/surface/quadrature.hpp"
#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/surface_support.hpp"

namespace pellicle::validation {

namespace {

SurfaceIntegrals totals(const SurfaceSimulation<3>& s, std::vector<double>& areas) {
  return integrate(s.cloud(), s.neighbours(), &s.cloud().field(s.pde()->unknown()), areas);
}

struct HalfPipeRun {
  double h;
  std::size_t points_start, points_end;
  double area_start, area_end, largest_change, phi_min, phi_max;
};

}  // namespace

Outcome surface_half_pipe(Resolution resolution) {
  Outcome out;
  std::vector<double> lengths = {0.1};
  if (resolution == Resolution::full) lengths = {0.1, 0.07, 0.05};
  Series change{
      "half_pipe_conservation", "Half pipe: relative change of the integral of phi", {"time"}, {}};
  Series area{"half_pipe_area", "Half pipe: area", {"time"}, {}};
  std::vector<HalfPipeRun> runs;
  std::vector<double> areas;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    const double h = lengths[r];
    char column[32];
    std::snprintf(column, sizeof column, "h = %g", h);
    change.columns.push_back(column);
    area.columns.push_back(column);
    auto run = builtin_surface<3>("surface_half_pipe.toml",
                                  {setting("surface.smoothing_length", h), "output.monitors={}"});
    auto& s = *run.simulation;
    const SurfaceIntegrals start = totals(s, areas);
    const auto& initial = s.cloud().field(s.pde()->unknown());
    HalfPipeRun m{h,
                  run.initial_points,
                  0,
                  start.area,
                  0.0,
                  0.0,
                  *std::min_element(initial.begin(), initial.end()),
                  *std::max_element(initial.begin(), initial.end())};
    if (r == 0) {
      change.rows.push_back({0.0});
      area.rows.push_back({0.0});
    }
    change.rows[0].push_back(0.0);
    area.rows[0].push_back(start.area);
    int step = 0;
    while (!s.finished()) {
      s.step();
      const SurfaceIntegrals now = totals(s, areas);
      const double relative = now.integral / start.integral - 1.0;
      m.largest_change = std::max(m.largest_change, std::abs(relative));
      const auto& phi = s.cloud().field(s.pde()->unknown());
      m.phi_min = std::min(m.phi_min, *std::min_element(phi.begin(), phi.end()));
      m.phi_max = std::max(m.phi_max, *std::max_element(phi.begin(), phi.end()));
      if (++step % 5 == 0) {  // every 0.05
        if (r == 0) {
          change.rows.push_back({s.time()});
          area.rows.push_back({s.time()});
        }
        const std::size_t row = static_cast<std::size_t>(step / 5);
        change.rows[row].push_back(relative);
        area.rows[row].push_back(now.area);
      }
      m.area_end = now.area;
    }
    m.points_end = s.cloud().size();
    runs.push_back(m);
  }
  out.table +=
      "\nHalf pipe, Δt = 0.01 to t = 2: largest relative change of ∫ φ dA\n\n| h | points "
      "t = 0 / 2 | area t = 0 / 2 | largest change | φ range over the run |\n"
      "|---|---|---|---|---|\n";
  for (const auto& m : runs) {
    char line[256];
    std::snprintf(line, sizeof line, "| %g | %zu / %zu | %.3f / %.3f | %.2e | [%.3f, %.3f] |\n",
                  m.h, m.points_start, m.points_end, m.area_start, m.area_end, m.largest_change,
                  m.phi_min, m.phi_max);
    out.table += line;
    char name[96];
    std::snprintf(name, sizeof name, "half pipe, h = %g: largest relative change of ∫ φ dA", m.h);
    out.checks.push_back({name, 100.0 * m.largest_change, 0.0, 0.0, 1.0, "%"});
  }
  if (runs.size() > 1)
    out.checks.push_back({"half pipe: order in h of the change of ∫ φ dA, h = 0.1 to 0.05",
                          order(runs.front().largest_change, runs.back().largest_change,
                                runs.front().h, runs.back().h),
                          1.0, 1.0, 10.0, ""});
  out.series.push_back(std::move(change));
  out.series.push_back(std::move(area));
  return out;
}

}  // namespace pellicle::validation
