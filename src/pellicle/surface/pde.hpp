#pragma once
//! PDEs solved on the moving cloud (Suchde & Kuhnert §4.2), chosen by name in a case's
//! `[pde]` table through the registry (pde_registry.cpp): adding one is a new file and one
//! registration line. A PDE owns its fields on the cloud and advances them by one implicit
//! step after the cloud has moved and its stencils are built on the new positions.

#include <memory>
#include <string>
#include <vector>

#include "pellicle/core/parameters.hpp"
#include "pellicle/surface/formula.hpp"

namespace pellicle {

template <int D>
class SurfaceSimulation;

template <int D>
class SurfacePde {
 public:
  virtual ~SurfacePde() = default;
  //! One line for run summaries.
  virtual std::string describe() const = 0;
  //! Create the fields on the cloud and set their values at t = 0.
  virtual void initialise(SurfaceSimulation<D>& s) = 0;
  //! Before the cloud moves (points at xⁿ, time tⁿ): explicit terms at time level n.
  virtual void before_move(SurfaceSimulation<D>& s) { (void)s; }
  //! φ from tⁿ to tⁿ⁺¹ = tⁿ + dt on the moved cloud. `divergence` holds ∇_M · v⁽ⁿ⁺¹⁾ per point.
  virtual void advance(SurfaceSimulation<D>& s, double dt,
                       const std::vector<double>& divergence) = 0;
  //! Index of the field φ the formulas read as `phi` (−1: none).
  virtual int unknown() const = 0;
  //! The exact solution, when the case gives one (errors in history.csv).
  virtual const PointFormula* exact() const { return nullptr; }
};

template <int D>
using SurfacePdeFactory = std::unique_ptr<SurfacePde<D>> (*)(ParameterReader& in);

template <int D>
struct SurfacePdeModel {
  std::string name, summary;
  SurfacePdeFactory<D> make;
};

//! Registered PDEs (pde_registry.cpp).
template <int D>
const std::vector<SurfacePdeModel<D>>& surface_pde_models();

//! A required formula key; problems (with the column within the formula) go to `in`.
PointFormula read_formula(ParameterReader& in, std::string_view key);
//! An optional one: `fallback` when absent (an empty fallback gives an empty formula).
PointFormula read_formula_or(ParameterReader& in, std::string_view key, std::string_view fallback);

}  // namespace pellicle
