#pragma once
//! The wave equation on a moving surface (Suchde & Kuhnert eq 42):
//!   D/Dt (Dφ/Dt) + (Dφ/Dt) ∇_M · v = c² Δ_M φ + f,
//! with φ(x, 0) = g₁ and Dφ/Dt(x, 0) = g₂ (eqs 43–44), integrated after each movement step by
//! eq 45,
//!   (φⁿ⁺¹ − 2φⁿ + φⁿ⁻¹)/Δt² + (φⁿ⁺¹ − φⁿ)/Δt ∇_M · vⁿ⁺¹ = c² Δ_M φⁿ⁺¹ + fⁿ,
//! where fⁿ is evaluated at the points' positions at tⁿ (before they move) and carried with
//! them, and φ⁻¹ = g₁ − Δt g₂ (eq 44 by a backward difference).

#include "pellicle/surface/pde.hpp"

namespace pellicle {

template <int D>
std::unique_ptr<SurfacePde<D>> make_wave(ParameterReader& in);

}  // namespace pellicle
