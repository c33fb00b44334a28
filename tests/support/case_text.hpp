#pragma once
// Build simulations for tests from case text, the same path users take.

#include <memory>
#include <string>
#include <vector>

#include "pellicle/io/build.hpp"
#include "pellicle/io/case.hpp"

namespace pellicle::testing {

template <int D>
std::unique_ptr<Simulation<D>> simulation_from_text(const std::string& text,
                                                    const std::vector<std::string>& overrides = {}) {
  const auto source = case_source_from_text(text, "<test case>", overrides);
  Case<D> c = read_case<D>(*source);
  return build_simulation<D>(c);
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
