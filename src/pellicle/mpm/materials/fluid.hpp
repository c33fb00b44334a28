#pragma once
//! Compressible Newtonian fluids (thesis ch. 4): gas and liquids, one class over the
//! equation of state (equations_of_state.hpp). At each point, from the strain rate D:
//!   σ = −(p + q) I + 2μ (D − ⅓ tr D I)                       Stokes condition (eq 4.1)
//!   q = ρ h |D_v| (c2 h |D_v| + c1 c),  D_v = min(tr D, 0)     Wilkins artificial viscosity
//!                                                             (eqs 4.11–4.12), h the cell
//!   ρ de/dt = σ : D                                           energy equation (eqs 4.8–4.10)
//! The energy is advanced with the pressure averaged over the step (p^n + p^{n+1})/2 and the
//! viscous and artificial terms at the new rate, solved together with p^{n+1} = p_c + Γ ρ e
//! (docs/theory/gas.md, where every step is derived).
//!
//! Case keys (table [[material]]):
//!   model = "gas"                ideal gas, p = (γ − 1) ρ e
//!     gamma                –     ratio of specific heats, > 1
//!   model = "barotropic-liquid"  p = −β tr ε (thesis eq 6.1)
//!     bulk_modulus         Pa    β > 0
//!   model = "tait-liquid"        p = K0/n [(ρ/ρ0)^n − 1]
//!     bulk_modulus         Pa    K0 > 0
//!     exponent             –     n > 0, default 7 (water)
//!   all fluids:
//!     density              kg/m³ reference density ρ0 (a body may override it), > 0
//!     viscosity            Pa s  shear viscosity μ ≥ 0, default 0
//!     artificial_viscosity       table {linear = c1, quadratic = c2}, each ≥ 0, default 0
//!     density_update       "continuity" (eq 4.7, default) or "cell-quadratic" (eqs 4.5–4.6)

#include <memory>

#include "pellicle/mpm/materials/equations_of_state.hpp"
#include "pellicle/mpm/materials/material.hpp"

namespace pellicle {

//! Constants of the viscous part of a fluid's stress.
struct FluidViscosity {
  double shear = 0.0;      //!< μ
  double linear = 0.0;     //!< c1 of the artificial viscosity
  double quadratic = 0.0;  //!< c2 of the artificial viscosity
};

template <int D, class Eos>
class Fluid final : public Material<D> {
 public:
  Fluid(Kinematics kinematics, double density, Eos eos, FluidViscosity viscosity,
        bool density_from_cells);

  void declare_columns(Particles<D>& points) override;
  void initialise(Particles<D>& points, long begin, long end,
                  const InitialState<D>& state) const override;
  void update(const MaterialStep<D>& step) const override;
  double max_signal_speed(const Particles<D>& points, long begin, long end,
                          double cell) const override;
  //! The compression work is internal energy here: no separate stored strain energy.
  double strain_energy(const Particles<D>&, long, long) const override { return 0.0; }
  double internal_energy(const Particles<D>& points, long begin, long end) const override;
  //! Volume-weighted mean equation-of-state pressure of the points, Σ V p / Σ V.
  double mean_pressure(const Particles<D>& points, long begin, long end) const;
  Sym<D> stress_from_strain(const Sym<D>& strain) const override;
  double density() const override { return density_; }
  bool is_fluid() const override { return true; }
  bool stress_from_state() const override { return true; }
  //! history.csv: `<body>.pressure` (mean_pressure) and `<body>.volume` (Σ V).
  std::vector<std::string> history_names() const override { return {"pressure", "volume"}; }
  void history_sums(const Particles<D>& points, long begin, long end,
                    std::vector<double>& sums) const override;
  void history_from_sums(const double* sums, std::vector<double>& out) const override;
  std::string flip_caution() const override {
    return "a fluid moved by FLIP, whose ringing instability (Brackbill 1988) grows noise in "
           "slow flow at a rate of about c/h; velocity_update = \"apic\" with a B-spline "
           "kernel, or \"pic\", avoids it (docs/theory/gas.md)";
  }
  bool density_from_cells() const override { return from_cells_; }
  //! Non-finite (or, for a gas, negative) internal energy; a point standing for more than
  //! kMostCellsPerPoint cells (a gas expanding into vacuum beyond what its points represent).
  typename Material<D>::PointCheck check_points(const Particles<D>& points, long begin, long end,
                                                double cell) const override;
  static constexpr double kMostCellsPerPoint = 64.0;

  //! Equation-of-state pressure of point p (without the artificial viscosity).
  double pressure(const Particles<D>& points, long p) const {
    const double rho = points.density[p];
    return eos_.cold_pressure(rho, trace<D>(points[this->strain_][p])) +
           eos_.gruneisen() * rho * points[energy_][p];
  }
  //! Artificial viscosity q at density ρ, sound speed c, volumetric rate tr D, cell h.
  double artificial_viscosity(double rho, double c, double volumetric_rate, double h) const {
    if (volumetric_rate >= 0.0) return 0.0;  // eq 4.12: compression only
    const double jump = h * -volumetric_rate;
    return rho * jump * (viscosity_.quadratic * jump + viscosity_.linear * c);
  }

 private:
  double density_;
  Column<double> energy_;  //!< specific internal energy e, J/kg
  Eos eos_;
  FluidViscosity viscosity_;
  bool from_cells_;
};

template <int D>
std::unique_ptr<Material<D>> make_gas(ParameterReader& parameters, Kinematics kinematics);
template <int D>
std::unique_ptr<Material<D>> make_barotropic_liquid(ParameterReader& parameters,
                                                    Kinematics kinematics);
template <int D>
std::unique_ptr<Material<D>> make_tait_liquid(ParameterReader& parameters, Kinematics kinematics);

}  // namespace pellicle
