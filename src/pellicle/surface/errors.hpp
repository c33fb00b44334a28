#pragma once
//! Measures of a surface solution: the relative L2 error against an exact solution
//! (Suchde & Kuhnert eq 34) and the mean of a formula over the points (e.g. eq 13's distance
//! from a sphere).

#include <cmath>
#include <limits>

#include "pellicle/surface/simulation.hpp"

namespace pellicle {

struct SolutionErrors {
  double relative_l2 = std::numeric_limits<double>::quiet_NaN();  //!< eq 34
  double max = std::numeric_limits<double>::quiet_NaN();  //!< max_i |φ_i − φ_exact(x_i)|
};

//! Against the PDE's exact solution at the current time (NaN without one).
template <int D>
SolutionErrors solution_errors(const SurfaceSimulation<D>& s) {
  SolutionErrors e;
  const SurfacePde<D>* pde = s.pde();
  if (!pde || !pde->exact()) return e;
  const auto& phi = s.cloud().field(pde->unknown());
  double diff = 0.0, norm = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < s.cloud().size(); ++i) {
    const double exact = (*pde->exact())(s.values_at(i, s.time()));
    diff += (phi[i] - exact) * (phi[i] - exact);
    norm += exact * exact;
    largest = std::max(largest, std::abs(phi[i] - exact));
  }
  e.relative_l2 = norm > 0.0 ? std::sqrt(diff / norm) : std::sqrt(diff);
  e.max = largest;
  return e;
}

//! (1/N) Σ_i f(point i) at the current time.
template <int D>
double mean_over_points(const SurfaceSimulation<D>& s, const PointFormula& f) {
  double sum = 0.0;
  for (std::size_t i = 0; i < s.cloud().size(); ++i) sum += f(s.values_at(i, s.time()));
  return s.cloud().size() ? sum / s.cloud().size() : 0.0;
}

}  // namespace pellicle
