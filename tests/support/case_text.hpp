#pragma once
// Build simulations for tests from case text, the same path users take.

#include <memory>
#include <string>
#include <vector>

#include "pellicle/io/build.hpp"
#include "pellicle/io/case.hpp"

namespace pellicle::testing {

template <int D>
std::unique_ptr<Simulation<D>> simulation_from_text(
    const std::string& text, const std::vector<std::string>& overrides = {}) {
  const auto source = case_source_from_text(text, "<test case>", overrides);
  Case<D> c = read_case<D>(*source);
  return build_simulation<D>(c);
}

//! The text of the InputError that reading and building `text` (2D or 3D, by the case)
//! raises, "" when it is accepted.
inline std::string problems_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    const auto source = case_source_from_text(text, "case.toml", sets);
    if (case_dimension(*source) == 2) {
      Case<2> c = read_case<2>(*source);
      build_simulation<2>(c);
    } else {
      Case<3> c = read_case<3>(*source);
      build_simulation<3>(c);
    }
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

//! Body mass-weighted mean of a point quantity.
template <int D, class F>
auto body_mean(const Particles<D>& p, int body, F&& value) {
  const auto& b = p.bodies[body];
  double mass = 0.0;
  decltype(value(0L)) sum = value(b.begin) * 0.0;
  for (long i = b.begin; i < b.end; ++i) {
    sum += p.mass[i] * value(i);
    mass += p.mass[i];
  }
  return decltype(sum)(sum / mass);
}

}  // namespace pellicle::testing

#include <fstream>
#include <sstream>

namespace pellicle::testing {

//! Text of a case file under cases/.
inline std::string case_file(const std::string& name) {
  std::ifstream in(std::string(PELLICLE_CASES_DIR) + "/" + name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

//! A fluid body's volume-weighted mean pressure (its material's first history value).
template <int D>
double fluid_pressure(const Simulation<D>& s, int body) {
  std::vector<double> values;
  const auto& b = s.points().bodies[body];
  s.material(b.material).history_values(s.points(), b.begin, b.end, values);
  return values.at(0);
}

//! Mass-weighted mean velocity of a body.
template <int D>
Vec<D> body_velocity(const Simulation<D>& s, int body) {
  return body_mean(s.points(), body, [&](long p) { return Vec<D>(s.points().velocity[p]); });
}

//! Times at which a sampled signal changes sign (linear interpolation between samples).
inline std::vector<double> sign_changes(const std::vector<double>& t,
                                        const std::vector<double>& f) {
  std::vector<double> out;
  for (std::size_t i = 1; i < f.size(); ++i)
    if ((f[i - 1] < 0.0) != (f[i] < 0.0))
      out.push_back(t[i - 1] + (t[i] - t[i - 1]) * f[i - 1] / (f[i - 1] - f[i]));
  return out;
}

}  // namespace pellicle::testing
