#include "pellicle/mpm/materials/fluid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "pellicle/core/ordered_sum.hpp"
#include "pellicle/mpm/materials/kinematics.hpp"

namespace pellicle {

template <int D, class Eos>
Fluid<D, Eos>::Fluid(Kinematics kinematics, double density, Eos eos, FluidViscosity viscosity,
                     bool density_from_cells)
    : Material<D>(kinematics),
      density_(density),
      eos_(eos),
      viscosity_(viscosity),
      from_cells_(density_from_cells) {}

template <int D, class Eos>
void Fluid<D, Eos>::declare_columns(Particles<D>& points) {
  Material<D>::declare_columns(points);  // the strain: tr ε drives the barotropic law (eq 6.1)
  energy_ = points.template declare<double>({column_names::internal_energy, "J/kg", true, true});
}

template <int D, class Eos>
void Fluid<D, Eos>::initialise(Particles<D>& points, long begin, long end,
                               const InitialState<D>& state) const {
  Material<D>::initialise(points, begin, end, state);
  for (long p = begin; p < end; ++p) points[energy_][p] = state.internal_energy;
}

template <int D, class Eos>
void Fluid<D, Eos>::update(const MaterialStep<D>& step) const {
  auto& pts = step.points;
  auto& strain = pts[this->strain_];
  auto& energy = pts[energy_];
  // Kinetic energy the transfers dissipated this step (APIC), if the transfer keeps it.
  const Column<double> heat_column = pts.columns.template find<double>(column_names::transfer_heat);
  const double* heat = heat_column.valid() ? pts[heat_column].data() : nullptr;
  const bool axisymmetric = this->kinematics() == Kinematics::axisymmetric;
  const double gruneisen = eos_.gruneisen();
  const double inv_dt = step.dt > 0.0 ? 1.0 / step.dt : 0.0;
  for (long p = step.begin; p < step.end; ++p) {
    const Sym<D> de = strain_increment<D>(step.velocity_gradient[p],
                                          axisymmetric ? step.hoop_rate[p] : 0.0, step.dt);
    const double dv = trace<D>(de);  // ΔV/V over the step
    const double rho_new = pts.density[p];
    const double rho_old = rho_new * (1.0 + dv);  // continuity (eq 4.7) run backwards
    const double strain_old = trace<D>(strain[p]);
    const double e_old = energy[p] + (heat ? heat[p] : 0.0);  // the transfers' heat
    const double p_old = eos_.cold_pressure(rho_old, strain_old) + gruneisen * rho_old * e_old;
    strain[p] += de;

    // Viscous stress 2μ D' and artificial viscosity q at the new rate (eqs 4.1, 4.11–4.12).
    const Sym<D> deviatoric = add_to_normal<D>(de, -(dv / 3.0));
    const Sym<D> viscous = (2.0 * viscosity_.shear * inv_dt) * deviatoric;
    const double c_old = std::sqrt(eos_.sound_speed_squared(rho_old, p_old));
    const double q = artificial_viscosity(rho_new, c_old, dv * inv_dt, step.cell);

    // Energy (eqs 4.8–4.10), Δe = (V^n/m) σ̄ : Δε with the pressure centred in time and
    // p^{n+1} = p_c(ρ^{n+1}) + Γ ρ^{n+1} e^{n+1}: linear in e^{n+1}.
    const double specific_dv = dv / rho_old;  // ΔV/m
    const double dissipation = (contract<D>(viscous, de) - q * dv) / rho_old;
    const double p_cold = eos_.cold_pressure(rho_new, strain_old + dv);
    const double e_new = (e_old + dissipation - 0.5 * (p_old + p_cold) * specific_dv) /
                         (1.0 + 0.5 * gruneisen * rho_new * specific_dv);
    energy[p] = e_new;
    const double p_new = p_cold + gruneisen * rho_new * e_new;

    pts.stress[p] = add_to_normal<D>(viscous, -(p_new + q));
  }
}

template <int D, class Eos>
double Fluid<D, Eos>::max_signal_speed(const Particles<D>& points, long begin, long end,
                                       double cell) const {
  // Stable step of a viscous element: Δt ≤ h / (Q + sqrt(Q² + c²)), Q the viscous speed
  // (docs/theory/gas.md). q is recovered from the stored stress, q = −tr σ/3 − p.
  const bool shear_term = cell > 0.0;
  auto speed = [&](double rho, double pressure_p, double stress_trace) {
    const double c = std::sqrt(eos_.sound_speed_squared(rho, pressure_p));
    const double q = std::max(0.0, -stress_trace / 3.0 - pressure_p);
    const double c1c = viscosity_.linear * c;
    double Q = 0.5 * (c1c + std::sqrt(c1c * c1c + 4.0 * viscosity_.quadratic * q / rho));
    if (shear_term) Q += D * (4.0 / 3.0) * viscosity_.shear / (rho * cell);
    return Q + std::sqrt(Q * Q + c * c);
  };
  // Four points at a time, their inputs gathered into arrays first: the three square roots
  // and four divisions per point then run as vector instructions, four points per instruction.
  constexpr int kLanes = 4;
  double fastest = 0.0;
  long p = begin;
  for (; p + kLanes <= end; p += kLanes) {
    double rho[kLanes], pressure_p[kLanes], stress_trace[kLanes], lane[kLanes];
    for (int k = 0; k < kLanes; ++k) {
      rho[k] = points.density[p + k];
      pressure_p[k] = pressure(points, p + k);
      stress_trace[k] = trace<D>(points.stress[p + k]);
    }
#pragma omp simd
    for (int k = 0; k < kLanes; ++k) lane[k] = speed(rho[k], pressure_p[k], stress_trace[k]);
    for (int k = 0; k < kLanes; ++k) fastest = std::max(fastest, lane[k]);
  }
  for (; p < end; ++p)
    fastest = std::max(fastest,
                       speed(points.density[p], pressure(points, p), trace<D>(points.stress[p])));
  return fastest;
}

namespace {

//! In-plane measure of a point (2D: its area; axisymmetric: its ring's cross-section, the
//! volume over 2π r; 3D: its volume). Within half a cell of the axis the hoop rate v_r/r, and
//! with it the volume, is only as good as the grid's v_r there, and V/(2π r) grows without
//! bound as r → 0: there the volume is measured against the innermost cells' ring, 2π (h/2).
template <int D>
double in_plane_measure(const Particles<D>& points, long p, bool axisymmetric, double cell) {
  if (!axisymmetric) return points.volume[p];
  const double r = std::max(points.position[p][0], 0.5 * cell);
  return points.volume[p] / (2.0 * std::numbers::pi * r);
}

//! Upper bound (Gershgorin) of the largest principal value of the in-plane strain: the
//! logarithm of the largest stretch since the start.
template <int D>
double largest_stretch_bound(const Sym<D>& e) {
  if constexpr (D == 2) {
    return std::max(e[0], e[1]) + std::abs(e[3]);
  } else {
    return std::max({e[0] + std::abs(e[5]) + std::abs(e[4]), e[1] + std::abs(e[5]) + std::abs(e[3]),
                     e[2] + std::abs(e[4]) + std::abs(e[3])});
  }
}

}  // namespace

template <int D, class Eos>
typename Material<D>::PointCheck Fluid<D, Eos>::check_points(const Particles<D>& points, long begin,
                                                             long end, double cell) const {
  // A gas's pressure is Γ ρ e: negative energy would make it pull.
  const bool thermal = eos_.gruneisen() > 0.0;
  const bool axisymmetric = this->kinematics() == Kinematics::axisymmetric;
  const double cell_measure = std::pow(cell, D);
  const auto& energy = points[energy_];
  const auto& strain = points[this->strain_];
  long first = end;
  double most = 0.0, widest = 0.0;  // in units of the point's measure: cell_measure later
  // Per point: its measure (the cells it covers, times the cell's), and the D-th power of its
  // spacing along its most stretched direction, (s0 e^ε1)^D = V e^(D ε1 − tr ε) with
  // s0 = (V e^−tr ε)^(1/D) the spacing it started with: one exponential, no root, per point.
  auto spacing_power = [&](long p, double measure) {
    const Sym<D>& e = strain[p];
    const double in_plane_trace = D == 2 ? e[0] + e[1] : e[0] + e[1] + e[2];
    return measure * std::exp(D * largest_stretch_bound<D>(e) - in_plane_trace);
  };
  for (long p = begin; p < end; ++p) {
    const double e = energy[p];
    if (!std::isfinite(e) || (thermal && e < 0.0)) first = std::min(first, p);
    const double measure = in_plane_measure(points, p, axisymmetric, cell);
    most = std::max(most, measure);
    widest = std::max(widest, spacing_power(p, measure));
  }
  const double most_cells = most / cell_measure;
  typename Material<D>::PointCheck check;
  check.spacing = std::pow(widest / cell_measure, 1.0 / D);
  if (widest > cell_measure)  // rare: find the point (the reduction keeps only the value)
    for (long p = begin; p < end && check.thinnest < 0; ++p)
      if (spacing_power(p, in_plane_measure(points, p, axisymmetric, cell)) == widest)
        check.thinnest = p;
  if (first < end) {
    check.invalid = first;
    check.why = "non-finite or negative specific internal energy";
  } else if (most_cells > kMostCellsPerPoint) {
    for (long p = begin; p < end && check.invalid < 0; ++p)
      if (in_plane_measure(points, p, axisymmetric, cell) == most) check.invalid = p;
    char text[200];
    std::snprintf(text, sizeof text,
                  "the gas has expanded into vacuum beyond what its points represent: the point "
                  "stands for %.3g cells (limit %g)",
                  most_cells, kMostCellsPerPoint);
    check.why = text;
  }
  return check;
}

template <int D, class Eos>
double Fluid<D, Eos>::internal_energy(const Particles<D>& points, long begin, long end) const {
  const auto& e = points[energy_];
  return ordered_sum(begin, end, [&](long p) { return points.mass[p] * e[p]; });
}

template <int D, class Eos>
void Fluid<D, Eos>::history_sums(const Particles<D>& points, long begin, long end,
                                 std::vector<double>& sums) const {
  const auto [pv, v] = ordered_sums<2>(begin, end, [&](long p, std::array<double, 2>& s) {
    s[0] += points.volume[p] * pressure(points, p);
    s[1] += points.volume[p];
  });
  sums.push_back(pv);
  sums.push_back(v);
}

template <int D, class Eos>
void Fluid<D, Eos>::history_from_sums(const double* sums, std::vector<double>& out) const {
  out.push_back(sums[1] > 0.0 ? sums[0] / sums[1] : 0.0);  // Σ V p / Σ V
  out.push_back(sums[1]);
}

template <int D, class Eos>
double Fluid<D, Eos>::mean_pressure(const Particles<D>& points, long begin, long end) const {
  std::vector<double> sums, values;
  history_sums(points, begin, end, sums);
  history_from_sums(sums.data(), values);
  return values[0];
}

template <int D, class Eos>
Sym<D> Fluid<D, Eos>::stress_from_strain(const Sym<D>& strain) const {
  Sym<D> sigma = Sym<D>::Zero();
  sigma.template head<3>().array() = -eos_.cold_pressure(density_, trace<D>(strain));
  return sigma;
}

namespace {

//! Keys every fluid shares: density, viscosity, artificial viscosity, density update.
struct FluidKeys {
  double density;
  FluidViscosity viscosity;
  bool from_cells;
};

FluidKeys read_fluid_keys(ParameterReader& in, Kinematics kinematics) {
  if (kinematics == Kinematics::plane_stress)
    in.fail("model",
            "a fluid needs grid.kinematics = \"plane-strain\", \"axisymmetric\" or a 3D grid "
            "(plane stress has no meaning for a fluid)");
  FluidKeys k;
  k.density = in.number("density", NumberRange::positive());
  k.viscosity.shear = in.number_or("viscosity", 0.0, NumberRange::non_negative());
  if (in.has("artificial_viscosity")) {
    auto q = in.table("artificial_viscosity");
    k.viscosity.linear = q->number_or("linear", 0.0, NumberRange::non_negative());
    k.viscosity.quadratic = q->number_or("quadratic", 0.0, NumberRange::non_negative());
  }
  k.from_cells = in.choice("density_update", {"continuity", "cell-quadratic"}, "continuity") ==
                 "cell-quadratic";
  return k;
}

template <int D, class Eos>
std::unique_ptr<Material<D>> make_fluid(const FluidKeys& k, Eos eos, Kinematics kinematics) {
  return std::make_unique<Fluid<D, Eos>>(kinematics, k.density, eos, k.viscosity, k.from_cells);
}

}  // namespace

template <int D>
std::unique_ptr<Material<D>> make_gas(ParameterReader& in, Kinematics kinematics) {
  const FluidKeys k = read_fluid_keys(in, kinematics);
  const double gamma = in.number("gamma", {1.0, 1e308, true, false});
  return make_fluid<D>(k, IdealGas{gamma}, kinematics);
}

template <int D>
std::unique_ptr<Material<D>> make_barotropic_liquid(ParameterReader& in, Kinematics kinematics) {
  const FluidKeys k = read_fluid_keys(in, kinematics);
  const double beta = in.number("bulk_modulus", NumberRange::positive());
  return make_fluid<D>(k, BarotropicLiquid{beta}, kinematics);
}

template <int D>
std::unique_ptr<Material<D>> make_tait_liquid(ParameterReader& in, Kinematics kinematics) {
  const FluidKeys k = read_fluid_keys(in, kinematics);
  const double bulk = in.number("bulk_modulus", NumberRange::positive());
  const double n = in.number_or("exponent", 7.0, NumberRange::positive());
  return make_fluid<D>(k, TaitLiquid{k.density, bulk, n}, kinematics);
}

template class Fluid<2, IdealGas>;
template class Fluid<3, IdealGas>;
template class Fluid<2, BarotropicLiquid>;
template class Fluid<3, BarotropicLiquid>;
template class Fluid<2, TaitLiquid>;
template class Fluid<3, TaitLiquid>;
template std::unique_ptr<Material<2>> make_gas<2>(ParameterReader&, Kinematics);
template std::unique_ptr<Material<3>> make_gas<3>(ParameterReader&, Kinematics);
template std::unique_ptr<Material<2>> make_barotropic_liquid<2>(ParameterReader&, Kinematics);
template std::unique_ptr<Material<3>> make_barotropic_liquid<3>(ParameterReader&, Kinematics);
template std::unique_ptr<Material<2>> make_tait_liquid<2>(ParameterReader&, Kinematics);
template std::unique_ptr<Material<3>> make_tait_liquid<3>(ParameterReader&, Kinematics);

}  // namespace pellicle
