// Linear elasticity at a point: the 3D, plane-stress and plane-strain laws, objectivity of the
// Jaumann update (IJNME eq 14) and the stored energy.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "pellicle/mpm/materials/linear_elastic.hpp"

namespace pellicle {
namespace {

constexpr double E = 2.0e5, nu = 0.3;

template <int D>
Particles<D> one_point(LinearElastic<D>& m, const Sym<D>& stress = Sym<D>::Zero()) {
  Particles<D> p;
  m.declare_columns(p);
  p.bodies.push_back({"b", 0, Vec<D>::Zero(), 0, 0, nullptr});
  p.add(Vec<D>::Zero(), Vec<D>::Zero(), 1.0, 1.0);
  p.stress[0] = stress;
  return p;
}

// One update with a constant velocity gradient L over dt.
template <int D>
void step(const LinearElastic<D>& m, Particles<D>& p, const Mat<D>& L, double dt,
          double hoop = 0.0) {
  const std::vector<Mat<D>> gradient{L};
  const std::vector<double> hoop_rate{hoop};
  m.update(MaterialStep<D>{p, gradient, hoop_rate, dt, 0, 1});
}

TEST(LinearElastic, UniaxialStress3D) {
  LinearElastic<3> m(Kinematics::solid, 1.0, E, nu);
  const double s = 123.0;
  Sym<3> strain;
  strain << s / E, -nu * s / E, -nu * s / E, 0, 0, 0;
  const Sym<3> stress = m.stress_from_strain(strain);
  EXPECT_NEAR(stress[0], s, 1e-9 * s);
  for (int k = 1; k < 6; ++k) EXPECT_NEAR(stress[k], 0.0, 1e-9 * s);
}

TEST(LinearElastic, UniaxialStressPlaneStress) {
  LinearElastic<2> m(Kinematics::plane_stress, 1.0, E, nu);
  Particles<2> p = one_point<2>(m);
  // Stretch along x at rate a with the lateral contraction of uniaxial stress.
  const double a = 1e-3, dt = 1.0;
  Mat<2> L;
  L << a, 0, 0, -nu * a;
  step(m, p, L, dt);
  EXPECT_NEAR(p.stress[0][0], E * a * dt, 1e-9 * E * a);
  EXPECT_NEAR(p.stress[0][1], 0.0, 1e-9 * E * a);
  EXPECT_EQ(p.stress[0][2], 0.0);  // σ_zz = 0 in plane stress
  EXPECT_NEAR(p.template named<Sym<2>>("strain")[0][2], -nu * a * dt,
              1e-15);  // thickness strain of uniaxial stress
}

TEST(LinearElastic, UniaxialStrainPlaneStrain) {
  LinearElastic<2> m(Kinematics::plane_strain, 1.0, E, nu);
  Particles<2> p = one_point<2>(m);
  const double a = 1e-3;
  Mat<2> L;
  L << a, 0, 0, 0;
  step(m, p, L, 1.0);
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  EXPECT_NEAR(p.stress[0][0], (lambda + 2 * mu) * a, 1e-9 * E * a);
  EXPECT_NEAR(p.stress[0][1], lambda * a, 1e-9 * E * a);
  EXPECT_NEAR(p.stress[0][2], lambda * a, 1e-9 * E * a);  // σ_zz of plane strain
  EXPECT_NEAR(m.max_signal_speed(p, 0, 1, 0.1), std::sqrt((lambda + 2 * mu) / 1.0), 1e-9);
}

TEST(LinearElastic, AxisymmetricHoopStrain) {
  LinearElastic<2> m(Kinematics::axisymmetric, 1.0, E, nu);
  Particles<2> p = one_point<2>(m);
  const double rate = 2e-3;  // v_r / r
  step<2>(m, p, Mat<2>::Zero(), 1.0, rate);
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  EXPECT_NEAR(p.stress[0][2], (lambda + 2 * mu) * rate, 1e-9 * E * rate);
  EXPECT_NEAR(p.stress[0][0], lambda * rate, 1e-9 * E * rate);
  EXPECT_NEAR(p.template named<Sym<2>>("strain")[0][2], rate, 1e-15);
}

TEST(LinearElastic, IsotropyUnderRotation3D) {
  LinearElastic<3> m(Kinematics::solid, 1.0, E, nu);
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 1e-3);
  Mat3 e;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) e(i, j) = n(rng);
  e = 0.5 * (e + e.transpose()).eval();
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Mat3 s = to_mat3<3>(m.stress_from_strain(from_mat3<3>(e)));
  const Mat3 s_rotated = to_mat3<3>(m.stress_from_strain(from_mat3<3>(R * e * R.transpose())));
  EXPECT_LT((s_rotated - R * s * R.transpose()).norm(), 1e-9 * s.norm());
}

// A rigid spin must rotate an existing stress, not change its invariants (Jaumann rate).
template <int D>
void check_spin_rotates_stress(Kinematics k) {
  LinearElastic<D> m(k, 1.0, E, nu);
  Sym<D> s0 = Sym<D>::Zero();
  s0[0] = 100.0;  // uniaxial along x
  Particles<D> p = one_point<D>(m, s0);
  const double omega = 1.0, angle = 0.5;
  const int steps = 20000;
  Mat<D> L = Mat<D>::Zero();
  L(0, 1) = -omega;
  L(1, 0) = omega;
  for (int i = 0; i < steps; ++i) step(m, p, L, angle / (omega * steps));
  const Mat3 s = to_mat3<D>(p.stress[0]);
  const double c = std::cos(angle), sn = std::sin(angle);
  EXPECT_NEAR(s(0, 0), 100.0 * c * c, 0.05);
  EXPECT_NEAR(s(1, 1), 100.0 * sn * sn, 0.05);
  EXPECT_NEAR(s(0, 1), 100.0 * c * sn, 0.05);
  EXPECT_NEAR(s.trace(), 100.0, 0.05);
}

TEST(LinearElastic, SpinRotatesStress2D) {
  check_spin_rotates_stress<2>(Kinematics::plane_strain);
}
TEST(LinearElastic, SpinRotatesStress3D) {
  check_spin_rotates_stress<3>(Kinematics::solid);
}

TEST(LinearElastic, StoredEnergyIsHalfStressStrain) {
  for (Kinematics k :
       {Kinematics::plane_strain, Kinematics::plane_stress, Kinematics::axisymmetric}) {
    LinearElastic<2> m(k, 1.0, E, nu);
    Sym<2> strain;
    strain << 1e-3, -4e-4, k == Kinematics::axisymmetric ? 2e-4 : 0.0, 3e-4;
    Sym<2> e = strain;
    const Sym<2> stress = m.stress_increment(e);  // e gains ε_zz in plane stress
    Particles<2> p = one_point<2>(m, stress);
    EXPECT_NEAR(m.strain_energy(p, 0, 1), 0.5 * contract<2>(stress, e), 1e-12 * E * 1e-6);
  }
}

}  // namespace
}  // namespace pellicle
