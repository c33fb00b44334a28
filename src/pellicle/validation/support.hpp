#pragma once
//! What the validation problems share: building a simulation from a built-in case, and body
//! averages.

#include <algorithm>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "pellicle/io/build.hpp"
#include "pellicle/io/builtin_cases.hpp"
#include "pellicle/io/case.hpp"

namespace pellicle::validation {

//! A built-in case with `overrides` (`key=value`), built (keeping the points `select`
//! chooses, when given: SimulationBuilder::select_points).
template <int D>
std::unique_ptr<Simulation<D>> builtin_simulation(const std::string& file,
                                                  const std::vector<std::string>& overrides,
                                                  PointSelection<D> select = {}) {
  const auto source = case_source_from_text(builtin_case(file), file, overrides);
  Case<D> c = read_case<D>(*source);
  return build_simulation<D>(c, std::move(select));
}

//! Mass-weighted mean velocity of a body.
template <int D>
Vec<D> body_velocity(const Simulation<D>& s, int body) {
  const auto& p = s.points();
  const auto& b = p.bodies[body];
  Vec<D> momentum = Vec<D>::Zero();
  double mass = 0.0;
  for (long i = b.begin; i < b.end; ++i) {
    momentum += p.mass[i] * p.velocity[i];
    mass += p.mass[i];
  }
  return momentum / mass;
}

//! Accepted error on one rung of a convergence ladder (a cell size or a time step `step`)
//! whose finest rung `finest` must meet `target`: a method of at least first order has at
//! most target × step / finest there, and every refinement must reduce the error, so it is
//! also at most the coarser rung's error `previous` (infinity on the first rung).
inline double ladder_bound(double target, double step, double finest, double previous) {
  return std::min(target * step / finest, previous);
}

}  // namespace pellicle::validation
