#pragma once
//! Equations of state of the fluid models, all of the form p = p_c(ρ, ε_v) + Γ ρ e: a part
//! p_c from density or volumetric strain and a thermal part Γ ρ e from the specific internal
//! energy e (docs/theory/gas.md). The fluid's energy update (eq 4.10) is written for this
//! form, so every model below gets the same time-centred energy balance.

#include <algorithm>
#include <cmath>

namespace pellicle {

//! Ideal gas, p = (γ − 1) ρ e (thesis eq 4.4); c² = γ p / ρ.
struct IdealGas {
  double gamma;
  double cold_pressure(double, double) const { return 0.0; }
  double gruneisen() const { return gamma - 1.0; }
  double sound_speed_squared(double rho, double p) const { return gamma * std::max(p, 0.0) / rho; }
};

//! Barotropic liquid, p = −β tr ε (thesis eq 6.1), ε the accumulated small strain;
//! c² = β / ρ.
struct BarotropicLiquid {
  double bulk_modulus;
  double cold_pressure(double, double volumetric_strain) const {
    return -bulk_modulus * volumetric_strain;
  }
  double gruneisen() const { return 0.0; }
  double sound_speed_squared(double rho, double) const { return bulk_modulus / rho; }
};

//! Tait liquid, p = B [(ρ/ρ0)^n − 1] with B = K0 / n (K0 the bulk modulus at ρ0);
//! c² = dp/dρ = (K0/ρ0) (ρ/ρ0)^(n−1).
struct TaitLiquid {
  double reference_density, bulk_modulus, exponent;
  double cold_pressure(double rho, double) const {
    return bulk_modulus / exponent * (std::pow(rho / reference_density, exponent) - 1.0);
  }
  double gruneisen() const { return 0.0; }
  double sound_speed_squared(double rho, double) const {
    return bulk_modulus / reference_density * std::pow(rho / reference_density, exponent - 1.0);
  }
};

}  // namespace pellicle
