#include "pellicle/validation/shock_tube.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pellicle/validation/support.hpp"

namespace pellicle::validation {
namespace {

std::vector<TubeSample> samples(const Simulation<2>& s, double gamma) {
  const auto& pts = s.points();
  const auto& energy = pts.named<double>("internal_energy");
  std::vector<TubeSample> out;
  out.reserve(pts.size());
  for (long i = 0; i < pts.size(); ++i)
    out.push_back({pts.position[i].x(), pts.density[i], pts.velocity[i].x(),
                   (gamma - 1.0) * pts.density[i] * energy[i], energy[i], pts.volume[i]});
  std::sort(out.begin(), out.end(),
            [](const TubeSample& a, const TubeSample& b) { return a.x < b.x; });
  return out;
}

}  // namespace

double shock_position(const std::vector<TubeSample>& tube, double p_star, double p_right) {
  const double middle = 0.5 * (p_star + p_right);
  double front = 0.0;
  for (const auto& s : tube)
    if (s.p > middle) front = s.x;
  return front;
}

TubeRun run_tube(const ShockTube& setup, int cells, const std::vector<std::string>& extra,
                 double p_star) {
  const double h = 1.0 / cells;
  std::vector<std::string> overrides;
  auto set = [&overrides](const char* format, auto... values) {
    char text[200];
    std::snprintf(text, sizeof text, format, values...);
    overrides.emplace_back(text);
  };
  set("grid.cell=%.17g", h);
  set("grid.upper=[1.0, %.17g]", h);
  set("solver.dt=%.17g", setup.dt_100 * 100.0 / cells);
  set("solver.end_time=%.17g", setup.end_time);
  set("material[0].gamma=%.17g", setup.gamma);
  const GasState* sides[2] = {&setup.left, &setup.right};
  for (int b = 0; b < 2; ++b) {
    const GasState& g = *sides[b];
    set("body[%d].density=%.17g", b, g.density);
    set("body[%d].internal_energy=%.17g", b, g.pressure / ((setup.gamma - 1.0) * g.density));
    set("body[%d].velocity=[%.17g, 0.0]", b, g.velocity);
    set("body[%d].region={shape=\"box\", lower=[%.17g, 0.0], upper=[%.17g, %.17g]}", b, 0.5 * b,
        0.5 * (b + 1), h);
  }
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  auto s = builtin_simulation<2>("sod_shock_tube.toml", overrides);
  const double e0 = s->state().total();
  TubeRun run;
  long step = 0;
  while (!s->finished()) {
    s->step();
    if (++step % 10 == 0 && s->time() > 0.2 * setup.end_time) {
      run.t.push_back(s->time());
      run.front.push_back(shock_position(samples(*s, setup.gamma), p_star, setup.right.pressure));
    }
  }
  run.tube = samples(*s, setup.gamma);
  run.energy_change = s->state().total() / e0 - 1.0;
  return run;
}

TubeErrors l1_errors(const std::vector<TubeSample>& tube, const ExactRiemann& exact, double t,
                     double height) {
  TubeErrors e;
  for (const auto& s : tube) {
    const GasState g = exact.sample((s.x - 0.5) / t);
    const double dx = s.volume / height;
    e.density += dx * std::abs(s.rho - g.density);
    e.velocity += dx * std::abs(s.u - g.velocity);
    e.pressure += dx * std::abs(s.p - g.pressure);
  }
  return e;
}

TubeErrors total_variation(const ExactRiemann& exact, double t) {
  TubeErrors tv;
  constexpr int kSamples = 100000;  // the fan is smooth; the jumps count whole at any spacing
  GasState last = exact.sample(-0.5 / t);
  for (int k = 1; k <= kSamples; ++k) {
    const GasState g = exact.sample((static_cast<double>(k) / kSamples - 0.5) / t);
    tv.density += std::abs(g.density - last.density);
    tv.velocity += std::abs(g.velocity - last.velocity);
    tv.pressure += std::abs(g.pressure - last.pressure);
    last = g;
  }
  return tv;
}

double plateau_mean(const std::vector<TubeSample>& tube, double a, double b,
                    double TubeSample::*column) {
  double sum = 0.0, n = 0.0;
  for (const auto& s : tube)
    if (s.x > a && s.x < b) sum += s.*column, n += 1.0;
  return n > 0.0 ? sum / n : 0.0;
}

Series tube_profile(const std::string& name, const std::string& title,
                    const std::vector<TubeSample>& tube, const ExactRiemann& exact, double t,
                    double gamma) {
  Series out{name,
             title,
             {"x", "density", "exact density", "velocity", "exact velocity", "pressure",
              "exact pressure", "internal energy", "exact internal energy"},
             {}};
  double last_x = -1.0;
  for (const auto& s : tube) {
    if (s.x == last_x) continue;  // the points across the tube repeat the same values
    last_x = s.x;
    const GasState g = exact.sample((s.x - 0.5) / t);
    out.rows.push_back({s.x, s.rho, g.density, s.u, g.velocity, s.p, g.pressure, s.e,
                        g.pressure / ((gamma - 1.0) * g.density)});
  }
  return out;
}

}  // namespace pellicle::validation
