// Wave equation on a deforming surface that collapses onto itself (Suchde & Kuhnert §4.2.4,
// Fig. 16; cases/surface_wave_creature.toml, a blobby creature in place of the paper's
// Armadillo). Eq 52 crushes every part of the surface that crosses x = 0 into that plane, so
// the surface folds there, its sides meet and self-contact deletes them. The paper shows
// pictures only; the checks are:
// - the run completes to t = 1.2 through the folds and deletions (a stencil that amplifies
//   stops it with exit 3);
// - self-contact has removed points (the topology changed);
// - the invariant of eq 42 with f = 0 on a closed surface: d/dt ∮ Dφ/Dt dA = ∮ c² Δ_M φ dA
//   = 0 (Reynolds' transport theorem turns the left side of eq 42, integrated, into the rate
//   of ∮ Dφ/Dt dA). Q(t) = Σ A_i (φ_i − φ_i⁽ⁿ⁻¹⁾)/Δt must keep Q(0) until contact first
//   deletes points (each deleted point takes its share away), within 2 % of ∮ |Dφ/Dt| dA:
//   the discrete Δ_M sums to zero only to the accuracy of the quadrature and the stencils.
#include <cmath>
#include <cstdio>

#include "pellicle/core/error.hpp"
#include "pellicle/surface/quadrature.hpp"
#include "pellicle/validation/problem.hpp"
#include "pellicle/validation/surface_support.hpp"

namespace pellicle::validation {

namespace {

struct RateIntegrals {
  double signed_total = 0.0;  //!< Σ A_i Dφ/Dt
  double magnitude = 0.0;     //!< Σ A_i |Dφ/Dt|
  double enclosed = 0.0;      //!< the enclosed volume
};

RateIntegrals rate_integrals(const SurfaceSimulation<3>& s, std::vector<double>& areas) {
  const auto& c = s.cloud();
  const std::vector<double>& phi = c.field(c.field_index("phi"));
  const std::vector<double>& previous = c.field(c.field_index("phi_previous"));
  RateIntegrals r;
  r.enclosed = integrate(c, s.neighbours(), nullptr, areas).enclosed;
  const double dt = s.settings().dt;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double rate = (phi[i] - previous[i]) / dt;
    r.signed_total += areas[i] * rate;
    r.magnitude += areas[i] * std::abs(rate);
  }
  return r;
}

}  // namespace

Outcome surface_wave_collapse(Resolution resolution) {
  Outcome out;
  const double h = resolution == Resolution::full ? 0.2 : 0.25;
  auto run =
      builtin_surface<3>("surface_wave_creature.toml", {setting("surface.smoothing_length", h)});
  auto& s = *run.simulation;
  Series counts{"points",
                "Wave on the collapsing creature: points, and points removed by contact",
                {"time", "points", "removed by contact"},
                {}};
  Series integrals{"integrals",
                   "Wave on the collapsing creature: enclosed volume and the integral of Dphi/Dt",
                   {"time", "enclosed volume", "integral of Dphi/Dt"},
                   {}};
  std::vector<double> areas;
  const RateIntegrals start = rate_integrals(s, areas);
  double drift = 0.0, first_removal = -1.0;
  std::string failure;
  try {
    while (!s.finished()) {
      s.step();
      const long removed = s.contact_total().removed + s.debris_removed();
      if (first_removal < 0.0 && removed > 0) first_removal = s.time();
      const RateIntegrals now = rate_integrals(s, areas);
      if (first_removal < 0.0)
        drift = std::max(drift, std::abs(now.signed_total - start.signed_total) / start.magnitude);
      counts.rows.push_back(
          {s.time(), static_cast<double>(s.cloud().size()), static_cast<double>(removed)});
      integrals.rows.push_back({s.time(), now.enclosed, now.signed_total});
    }
  } catch (const NumericalError& e) {
    failure = e.what();
  }
  char text[500];
  std::snprintf(text, sizeof text,
                "| h | points | reached t | chambers | deleted by contact (removed by the repair) "
                "| first removal | largest change of the integral of Dphi/Dt before it |\n"
                "|---|---|---|---|---|---|---|\n| %g | %zu → %zu | %g | %d | %ld (%ld) | t = %g | "
                "%.3g %% |\n",
                h, run.initial_points, s.cloud().size(), s.time(), s.cloud().chamber_count(),
                s.contact_total().removed, s.debris_removed(), first_removal, 100.0 * drift);
  out.table = text;
  if (!failure.empty()) out.table += "\nStopped: " + failure + "\n";
  const double end = s.settings().end_time;
  out.checks.push_back({"time reached", s.time(), end, end - 1e-9, end + 1e-9, ""});
  out.checks.push_back({"points removed by self-contact",
                        static_cast<double>(s.contact_total().removed + s.debris_removed()), 1.0,
                        1.0, static_cast<double>(run.initial_points), ""});
  out.checks.push_back({"change of the integral of Dphi/Dt before contact (of its magnitude)",
                        100.0 * drift, 0.0, 0.0, 2.0, "%"});
  out.series.push_back(std::move(counts));
  out.series.push_back(std::move(integrals));
  return out;
}

}  // namespace pellicle::validation
