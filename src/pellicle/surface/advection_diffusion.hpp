#pragma once
//! Convection–diffusion–reaction on a moving surface (Suchde & Kuhnert eq 28):
//!   Dφ/Dt + φ ∇_M · v = α Δ_M φ + f,
//! after each movement step integrated by the first-order implicit step of eq 29,
//!   (φⁿ⁺¹ − φⁿ)/Δt + φⁿ⁺¹ ∇_M · vⁿ⁺¹ = α Δ_M φⁿ⁺¹ + k φⁿ⁺¹ + s,
//! with the reaction f = k φ + s split into an implicit coefficient k (`reaction`) and an
//! explicit source s (`source`), both formulas evaluated at tⁿ⁺¹ on the moved points.

#include "pellicle/surface/pde.hpp"

namespace pellicle {

template <int D>
std::unique_ptr<SurfacePde<D>> make_advection_diffusion(ParameterReader& in);

}  // namespace pellicle
