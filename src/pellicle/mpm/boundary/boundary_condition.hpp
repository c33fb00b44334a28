#pragma once
//! Boundary conditions chosen by name in a case's `[[boundary]]` tables (registry.cpp: one
//! line per model). Each is a step hook (step_hook.hpp); the grid's faces (fixed, slip,
//! free) are the grid's own and need none.

#include <memory>
#include <string>
#include <vector>

#include "pellicle/core/parameters.hpp"
#include "pellicle/mpm/step_hook.hpp"

namespace pellicle {

template <int D>
using BoundaryFactory = std::unique_ptr<StepHook<D>> (*)(ParameterReader& parameters);

template <int D>
struct BoundaryModel {
  std::string name;
  std::string summary;
  BoundaryFactory<D> make;
};

template <int D>
const std::vector<BoundaryModel<D>>& boundary_models();

}  // namespace pellicle
