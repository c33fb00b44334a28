// Convection–diffusion–reaction and waves on the expanding sphere (Suchde & Kuhnert §4.2.1
// and §4.2.4; cases/surface_cdr_sphere.toml, cases/surface_wave_sphere.toml): relative L2
// errors at t = 1 (eq 34) against the manufactured solutions, and their orders, against the
// paper's Tables 2, 3 and 4. Each error should be within a factor 1.5 of the paper's and each
// order within 0.2 of the paper's; orders in h are measured, as the paper's, against the
// number of points at t = 0 (r = log(e₁/e₂) / log(√(N₂/N₁))).
#include <cmath>
#include <cstdio>

#include "pellicle/app/validation/problem.hpp"
#include "pellicle/app/validation/surface_support.hpp"

namespace pellicle::validation {

namespace {

struct Row {
  double parameter;  //!< h or Δt
  double paper_error, paper_order;
};

struct Measured {
  double error;
  std::size_t points;
};

Measured run_case(const char* file, double h, double dt) {
  auto run = builtin_surface<3>(file, {setting("surface.smoothing_length", h),
                                       setting("solver.dt", dt), "output.monitors={}"});
  run.simulation->run();
  return {solution_errors(*run.simulation).relative_l2, run.initial_points};
}

//! One table: errors and orders against the paper's, into checks and markdown.
void compare(Outcome& out, const char* label, const char* parameter_name,
             const std::vector<Row>& rows, const std::vector<Measured>& measured, bool in_h,
             std::string& table) {
  char line[256];
  std::snprintf(line, sizeof line,
                "\n%s\n\n| %s | N | error | paper | order | paper order |\n|---|---|---|---|---|---|\n",
                label, parameter_name);
  table += line;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    double r = std::nan("");
    if (k > 0)
      r = in_h ? order(measured[k - 1].error, measured[k].error,
                       1.0 / std::sqrt(double(measured[k - 1].points)),
                       1.0 / std::sqrt(double(measured[k].points)))
               : order(measured[k - 1].error, measured[k].error, rows[k - 1].parameter,
                       rows[k].parameter);
    std::snprintf(line, sizeof line, "| %g | %zu | %.3g | %.3g | %.2f | %.2f |\n",
                  rows[k].parameter, measured[k].points, measured[k].error, rows[k].paper_error,
                  r, rows[k].paper_order);
    table += line;
    char name[160];
    std::snprintf(name, sizeof name, "%s, %s = %g: error / paper's", label, parameter_name,
                  rows[k].parameter);
    out.checks.push_back({name, measured[k].error / rows[k].paper_error, 1.0, 1.0 / 1.5, 1.5, ""});
    if (k > 0) {
      std::snprintf(name, sizeof name, "%s, %s = %g: order", label, parameter_name,
                    rows[k].parameter);
      out.checks.push_back(
          {name, r, rows[k].paper_order, rows[k].paper_order - 0.2, rows[k].paper_order + 0.2, ""});
    }
  }
}

}  // namespace

Outcome surface_cdr_sphere(Resolution resolution) {
  const bool full = resolution == Resolution::full;
  Outcome out;
  std::string table;
  // Table 2: Δt = 0.4 h².
  std::vector<Row> spatial = {{0.4, 6.57e-2, 0}, {0.2, 1.93e-2, 1.85}};
  if (full) spatial.insert(spatial.end(), {{0.1, 4.76e-3, 1.98}, {0.05, 1.19e-3, 1.98}});
  std::vector<Measured> m;
  for (const auto& row : spatial)
    m.push_back(run_case("surface_cdr_sphere.toml", row.parameter, 0.4 * row.parameter * row.parameter));
  compare(out, "Table 2 (Δt = 0.4 h²)", "h", spatial, m, true, table);
  // Table 3: h = 0.1 (fast: h = 0.2), Δt = 0.01 / 2^k.
  const double h = full ? 0.1 : 0.2;
  std::vector<Row> temporal = {{0.01, 5.45e-2, 0}, {0.005, 2.74e-2, 0.99}};
  if (full) temporal.insert(temporal.end(), {{0.0025, 1.38e-2, 0.99}, {0.00125, 6.99e-3, 0.98},
                                             {0.000625, 3.56e-3, 0.97}});
  m.clear();
  for (const auto& row : temporal) m.push_back(run_case("surface_cdr_sphere.toml", h, row.parameter));
  compare(out, full ? "Table 3 (h = 0.1)" : "Table 3 (h = 0.2; the paper's h = 0.1 in --full)",
          "dt", temporal, m, false, table);
  out.table = table;
  return out;
}

Outcome surface_wave_sphere(Resolution resolution) {
  const bool full = resolution == Resolution::full;
  Outcome out;
  std::string table;
  std::vector<Row> rows = {{0.4, 7.88e-3, 0}, {0.2, 1.96e-3, 2.1}};
  if (full) rows.insert(rows.end(), {{0.1, 4.90e-4, 1.95}, {0.05, 1.23e-4, 1.98}});
  std::vector<Measured> m;
  for (const auto& row : rows)
    m.push_back(run_case("surface_wave_sphere.toml", row.parameter, row.parameter / 20.0));
  compare(out, "Table 4 (Δt = h/20)", "h", rows, m, true, table);
  out.table = table;
  return out;
}

}  // namespace pellicle::validation
