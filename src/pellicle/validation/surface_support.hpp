#pragma once
//! What the surface validation problems share: a simulation from a built-in surface case
//! with overrides, run to its end, and convergence orders.

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "pellicle/io/builtin_cases.hpp"
#include "pellicle/io/case.hpp"
#include "pellicle/io/surface_case.hpp"
#include "pellicle/surface/errors.hpp"

namespace pellicle::validation {

template <int D>
struct SurfaceRun {
  SurfaceCase<D> c;
  std::unique_ptr<SurfaceSimulation<D>> simulation;
  std::size_t initial_points = 0;
};

template <int D>
SurfaceRun<D> builtin_surface(const std::string& file, const std::vector<std::string>& overrides) {
  const auto source = case_source_from_text(builtin_case(file), file, overrides);
  SurfaceRun<D> r;
  r.c = read_surface_case<D>(*source);
  r.simulation = build_surface_simulation<D>(r.c);
  r.initial_points = r.simulation->cloud().size();
  return r;
}

//! "key=%g" for --set style overrides.
inline std::string setting(const char* key, double value) {
  char text[128];
  std::snprintf(text, sizeof text, "%s=%.17g", key, value);
  return text;
}

//! Order of convergence between two errors at resolutions a and b (a coarser).
inline double order(double error_a, double error_b, double resolution_a, double resolution_b) {
  return std::log(error_a / error_b) / std::log(resolution_a / resolution_b);
}

}  // namespace pellicle::validation
