// Fluids at a point (thesis ch. 4): the equations of state, the energy equation under
// adiabatic compression (the isentrope p ρ^−γ = const) and under shear (viscous heating
// μ γ̇²/ρ), the artificial viscosity only in compression, the time-step speed; and the
// exact Riemann solver against the published Sod star state.
#include <gtest/gtest.h>

#include <cmath>

#include "pellicle/mpm/materials/fluid.hpp"
#include "pellicle/validation/riemann.hpp"

namespace pellicle {
namespace {

Particles<2> one_point(Material<2>& fluid, double rho, double e) {
  Particles<2> p;
  fluid.declare_columns(p);
  p.bodies.push_back({"b", 0, Vec2::Zero(), 0, 0, nullptr});
  p.add(Vec2::Zero(), Vec2::Zero(), rho, rho);
  p.named<double>("internal_energy")[0] = e;
  return p;
}

//! One step with a constant velocity gradient; the density follows continuity first, as in
//! Simulation::update_materials.
template <class Eos>
void step(const Fluid<2, Eos>& fluid, Particles<2>& p, const Mat<2>& L, double dt,
          double cell = 0.1) {
  p.density[0] /= 1.0 + dt * L.trace();
  p.volume[0] = p.mass[0] / p.density[0];
  const std::vector<Mat<2>> gradient{L};
  const std::vector<double> hoop;
  fluid.update(MaterialStep<2>{p, gradient, hoop, dt, 0, 1, cell});
}

TEST(Fluid, AdiabaticCompressionFollowsTheIsentrope) {
  const double gamma = 1.4;
  Fluid<2, IdealGas> gas(Kinematics::plane_strain, 1.0, IdealGas{gamma}, {}, false);
  Particles<2> p = one_point(gas, 1.0, 2.5);
  const double entropy = gas.pressure(p, 0) / std::pow(1.0, gamma);
  const Mat<2> L = -0.5 * Mat<2>::Identity();  // uniform compression in the plane
  for (int i = 0; i < 1000; ++i) step(gas, p, L, 1e-3);
  ASSERT_GT(p.density[0], 2.0);  // compressed to more than twice the density
  // Time-centred pressure: second order in Δt (1.1e-7 relative here; 2.8e-4 with p^n alone).
  EXPECT_NEAR(gas.pressure(p, 0) / std::pow(p.density[0], gamma), entropy, 1e-6 * entropy);
  EXPECT_NEAR(p.stress[0][0], -gas.pressure(p, 0), 1e-12);
  EXPECT_NEAR(p.stress[0][2], -gas.pressure(p, 0), 1e-12);  // σ_zz: plane strain
  EXPECT_NEAR(p.stress[0][3], 0.0, 1e-15);
}

TEST(Fluid, ShearHeatsAtTheViscousDissipationRate) {
  const double mu = 0.3, rate = 2.0, rho = 1.5, dt = 1e-3;
  Fluid<2, BarotropicLiquid> liquid(Kinematics::plane_strain, rho, BarotropicLiquid{1e3},
                                    {mu, 0.0, 0.0}, false);
  Particles<2> p = one_point(liquid, rho, 0.0);
  Mat<2> L = Mat<2>::Zero();
  L(0, 1) = rate;  // simple shear: D_xy = rate/2, 2μ D:D = μ rate²
  for (int i = 0; i < 100; ++i) step(liquid, p, L, dt);
  EXPECT_NEAR(p.named<double>("internal_energy")[0], mu * rate * rate / rho * 100 * dt, 1e-12);
  EXPECT_NEAR(p.stress[0][3], mu * rate, 1e-12);  // τ_xy = 2μ D_xy
  EXPECT_NEAR(p.stress[0][0], 0.0, 1e-12);
}

TEST(Fluid, ArtificialViscosityActsOnlyInCompression) {
  const FluidViscosity q{0.0, 0.5, 2.0};
  Fluid<2, IdealGas> gas(Kinematics::plane_strain, 1.0, IdealGas{1.4}, q, false);
  const double rho = 1.3, c = 2.0, h = 0.1, rate = -4.0;
  EXPECT_DOUBLE_EQ(gas.artificial_viscosity(rho, c, -rate, h), 0.0);
  // q = ρ h|D|(c2 h|D| + c1 c) (thesis eqs 4.11–4.12)
  EXPECT_NEAR(gas.artificial_viscosity(rho, c, rate, h), rho * 0.4 * (2.0 * 0.4 + 0.5 * c), 1e-14);
}

TEST(Fluid, SignalSpeedIsTheSoundSpeedWithoutViscosity) {
  Fluid<2, IdealGas> gas(Kinematics::plane_strain, 1.0, IdealGas{1.4}, {}, false);
  Particles<2> p = one_point(gas, 0.125, 2.0);
  step(gas, p, Mat<2>::Zero(), 0.0);  // settle σ = −p I
  EXPECT_NEAR(gas.max_signal_speed(p, 0, 1, 0.01), std::sqrt(1.4 * 0.1 / 0.125), 1e-14);
  // A viscous gas: Δt ≤ h/(Q + sqrt(Q² + c²)), Q = 2·(4/3)μ/(ρh) in 2D.
  Fluid<2, IdealGas> viscous(Kinematics::plane_strain, 1.0, IdealGas{1.4}, {0.01, 0, 0}, false);
  viscous.declare_columns(p);  // the columns the first gas declared
  const double c = std::sqrt(1.4 * 0.1 / 0.125), Q = 2.0 * 4.0 / 3.0 * 0.01 / (0.125 * 0.01);
  EXPECT_NEAR(viscous.max_signal_speed(p, 0, 1, 0.01), Q + std::sqrt(Q * Q + c * c), 1e-12);
}

TEST(Fluid, EquationsOfState) {
  EXPECT_DOUBLE_EQ(BarotropicLiquid{2.0e9}.cold_pressure(1000.0, -1e-3), 2.0e6);
  const TaitLiquid water{1000.0, 2.2e9, 7.0};
  EXPECT_DOUBLE_EQ(water.cold_pressure(1000.0, 0.0), 0.0);
  // c² = dp/dρ, checked by central differences.
  const double rho = 1010.0, d = 1e-3;
  const double dp = (water.cold_pressure(rho + d, 0) - water.cold_pressure(rho - d, 0)) / (2 * d);
  EXPECT_NEAR(water.sound_speed_squared(rho, 0.0), dp, 1e-6 * dp);
}

TEST(ExactRiemann, SodStarStateMatchesPublishedValues) {
  // Toro, Riemann Solvers and Numerical Methods for Fluid Dynamics, Table 4.3 (test 1).
  const validation::ExactRiemann sod({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 1.4);
  EXPECT_NEAR(sod.star_pressure(), 0.30313, 5e-6);
  EXPECT_NEAR(sod.star_velocity(), 0.92745, 5e-6);
  EXPECT_NEAR(sod.star_density_left(), 0.42632, 5e-6);
  EXPECT_NEAR(sod.star_density_right(), 0.26557, 5e-6);
  EXPECT_NEAR(sod.right_shock_speed(), 1.75216, 5e-5);
  // The sampled solution: undisturbed states outside the waves, the star state between.
  EXPECT_DOUBLE_EQ(sod.sample(-2.0).density, 1.0);
  EXPECT_DOUBLE_EQ(sod.sample(2.0).density, 0.125);
  EXPECT_NEAR(sod.sample(1.0).density, 0.26557, 5e-6);
  EXPECT_NEAR(sod.sample(0.5).density, 0.42632, 5e-6);
  // Inside the fan the flow is isentropic: p ρ^−γ equals the left state's.
  const validation::GasState fan = sod.sample(-0.5);
  EXPECT_NEAR(fan.pressure / std::pow(fan.density, 1.4), 1.0, 1e-12);
}

TEST(ExactRiemann, RefusesVacuumGeneratingData) {
  EXPECT_THROW(validation::ExactRiemann({1.0, -10.0, 0.1}, {1.0, 10.0, 0.1}, 1.4),
               std::invalid_argument);
}

}  // namespace
}  // namespace pellicle
