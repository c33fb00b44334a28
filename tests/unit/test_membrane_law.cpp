// The membrane law in its local frame (thesis ch. 5; IJNME §3): uniaxial and plane stress,
// the one-way (wrinkling) option and its tension-field form, and what the total-strain
// rotation does when the frame turns.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

#include "pellicle/mpm/materials/membrane.hpp"

namespace pellicle {
namespace {

constexpr double E = 1.0e6, nu = 0.3;

template <int D>
Particles<D> one_point(Membrane<D>& m, const Vec<D>& tangent, const Vec<D>& normal,
                       const Sym<D>& strain) {
  Particles<D> p;
  m.declare_columns(p);
  p.bodies.push_back({"m", 0, Vec<D>::Zero(), 0, 0, nullptr});
  p.add(Vec<D>::Zero(), Vec<D>::Zero(), 1.0, 1.0);
  p.template named<Sym<D>>("strain")[0] = strain;
  p.template named<Vec<D>>("tangent")[0] = tangent;
  p.template named<Vec<D>>("normal")[0] = normal;
  return p;
}

template <int D>
void update(const Membrane<D>& m, Particles<D>& p, const Mat<D>& L, double dt) {
  const std::vector<Mat<D>> gradient{L};
  const std::vector<double> hoop{0.0};
  m.update(MaterialStep<D>{p, gradient, hoop, dt, 0, 1});
}

TEST(MembraneLaw, StringCarriesOnlyTangentStress) {
  // A string at 30° stretched along itself: σ = E e t⊗t, nothing across it (eqs 5.5–5.9).
  Membrane<2> m(Kinematics::plane_strain, 1.0, E, nu, MembraneLaw::uniaxial, false);
  const double a = std::numbers::pi / 6;
  const Vec2 t(std::cos(a), std::sin(a)), n(-t.y(), t.x());
  Particles<2> p = one_point<2>(m, t, n, Sym<2>::Zero());
  const double e = 1e-3;
  update(m, p, Mat<2>(e * t * t.transpose()), 1.0);
  const Mat3 s = to_mat3<2>(p.stress[0]);
  EXPECT_NEAR(t.dot(s.topLeftCorner<2, 2>() * t), E * e, 1e-9 * E * e);
  EXPECT_NEAR(n.dot(s.topLeftCorner<2, 2>() * n), 0.0, 1e-9 * E * e);
  EXPECT_NEAR(t.dot(s.topLeftCorner<2, 2>() * n), 0.0, 1e-9 * E * e);
  EXPECT_EQ(s(2, 2), 0.0);
  // The stored strain is the uniaxial one: lateral strains −ν e (eq 5.6).
  const Mat3 strain = to_mat3<2>(p.named<Sym<2>>("strain")[0]);
  EXPECT_NEAR(n.dot(strain.topLeftCorner<2, 2>() * n), -nu * e, 1e-15);
  EXPECT_NEAR(strain(2, 2), -nu * e, 1e-15);
}

TEST(MembraneLaw, PlaneStressMembraneIn2DKeepsOutOfPlaneStress) {
  // Plane strain along z: σ11 = E e/(1 − ν²), σ22 (z) = ν σ11, σ33 = 0 (eqs 5.12–5.15).
  Membrane<2> m(Kinematics::plane_strain, 1.0, E, nu, MembraneLaw::plane_stress, false);
  Particles<2> p = one_point<2>(m, Vec2(1, 0), Vec2(0, 1), Sym<2>::Zero());
  const double e = 1e-3;
  Mat<2> L = Mat<2>::Zero();
  L(0, 0) = e;
  update(m, p, L, 1.0);
  EXPECT_NEAR(p.stress[0][0], E * e / (1 - nu * nu), 1e-6);
  EXPECT_NEAR(p.stress[0][2], nu * E * e / (1 - nu * nu), 1e-6);
  EXPECT_NEAR(p.stress[0][1], 0.0, 1e-9);
  EXPECT_NEAR(p.named<Sym<2>>("strain")[0][1], -nu / (1 - nu) * e, 1e-15);  // ε3' (eq 5.12)
}

TEST(MembraneLaw, AxisymmetricMembraneFeelsTheHoopStrain) {
  // An axisymmetric membrane (an airbag's wall): the hoop direction is its second in-surface
  // direction, strained by v_r/r; a radial expansion with no meridional stretch gives
  // σθθ = E e/(1 − ν²) and σ along the meridian ν times that.
  Membrane<2> m(Kinematics::axisymmetric, 1.0, E, nu, MembraneLaw::plane_stress, false);
  Particles<2> p = one_point<2>(m, Vec2(0, 1), Vec2(1, 0), Sym<2>::Zero());  // meridian along z
  const std::vector<Mat<2>> gradient{Mat<2>::Zero()};
  const std::vector<double> hoop{1e-3};
  m.update(MaterialStep<2>{p, gradient, hoop, 1.0, 0, 1});
  EXPECT_NEAR(p.stress[0][2], E * 1e-3 / (1 - nu * nu), 1e-6);
  EXPECT_NEAR(p.stress[0][1], nu * E * 1e-3 / (1 - nu * nu), 1e-6);
  EXPECT_NEAR(p.stress[0][0], 0.0, 1e-9);  // nothing through the thickness (radial here)
}

TEST(MembraneLaw, PlaneStressIn3DHasInPlaneShear) {
  Membrane<3> m(Kinematics::solid, 1.0, E, nu, MembraneLaw::plane_stress, false);
  Sym<3> strain = Sym<3>::Zero();
  strain << 1e-3, 5e-4, 0.0, 0.0, 0.0, 2e-4;  // xx, yy, zz, yz, xz, xy
  Particles<3> p = one_point<3>(m, Vec3::UnitX(), Vec3::UnitZ(), strain);
  update<3>(m, p, Mat3::Zero(), 0.0);
  const double C = E / (1 - nu * nu);
  EXPECT_NEAR(p.stress[0][0], C * (1e-3 + nu * 5e-4), 1e-6);
  EXPECT_NEAR(p.stress[0][1], C * (5e-4 + nu * 1e-3), 1e-6);
  EXPECT_NEAR(p.stress[0][5], E / (1 + nu) * 2e-4, 1e-6);
  EXPECT_NEAR(p.stress[0][2], 0.0, 1e-9);
  // The same strain seen in a frame turned in the plane gives the same stress tensor.
  const Vec3 t1 = Vec3(1, 1, 0).normalized();
  Particles<3> q = one_point<3>(m, t1, Vec3::UnitZ(), strain);
  update<3>(m, q, Mat3::Zero(), 0.0);
  EXPECT_LT((q.stress[0] - p.stress[0]).norm(), 1e-9 * p.stress[0].norm());
}

TEST(MembraneLaw, OneWayStringCarriesNoCompressionButRemembersIt) {
  Membrane<2> m(Kinematics::plane_strain, 1.0, E, 0.0, MembraneLaw::uniaxial, true);
  Particles<2> p = one_point<2>(m, Vec2(0, 1), Vec2(-1, 0), Sym<2>::Zero());
  Mat<2> L = Mat<2>::Zero();
  L(1, 1) = -0.01;  // shorten by 1%
  update(m, p, L, 1.0);
  EXPECT_EQ(p.stress[0].norm(), 0.0);
  EXPECT_NEAR(p.named<Sym<2>>("strain")[0][1], -0.01,
              1e-15);  // the slack is remembered (IJNME §3.2)
  L(1, 1) = 0.015;     // stretch back past the slack: tension from the net strain only
  update(m, p, L, 1.0);
  EXPECT_NEAR(p.stress[0][1], E * 0.005, 1e-6);
}

TEST(MembraneLaw, TensionFieldWrinklesAndSlackens) {
  Membrane<3> m(Kinematics::solid, 1.0, E, nu, MembraneLaw::plane_stress, true);
  double e22, s11, s22, s12;
  // Taut: biaxial tension is the plane-stress law.
  e22 = 1e-3;
  m.local_stress(2e-3, e22, 0.0, s11, s22, s12);
  EXPECT_NEAR(s22, E / (1 - nu * nu) * (1e-3 + nu * 2e-3), 1e-6);
  // Wrinkled: tension along 1', strong compression along 2': uniaxial E e1 along 1'.
  e22 = -5e-3;
  m.local_stress(2e-3, e22, 0.0, s11, s22, s12);
  EXPECT_NEAR(s11, E * 2e-3, 1e-6);
  EXPECT_NEAR(s22, 0.0, 1e-9);
  // Wrinkled along a principal direction at 45°: e = (1e-3, 1e-3, shear 2e-3) has
  // principal strains 3e-3 and −1e-3 along (1, 1) and (1, −1).
  e22 = 1e-3;
  m.local_stress(1e-3, e22, 2e-3, s11, s22, s12);
  EXPECT_NEAR(s11, 0.5 * E * 3e-3, 1e-6);
  EXPECT_NEAR(s22, 0.5 * E * 3e-3, 1e-6);
  EXPECT_NEAR(s12, 0.5 * E * 3e-3, 1e-6);
  // Slack: compression both ways carries nothing.
  e22 = -1e-3;
  m.local_stress(-2e-3, e22, 0.0, s11, s22, s12);
  EXPECT_EQ(s11, 0.0);
  EXPECT_EQ(s22, 0.0);
}

TEST(MembraneLaw, StrainMovesWithTheFrame) {
  // A stretched string turned rigidly through 90° (no stretching: L = 0, only the frame
  // turns), in 1000 steps or in one jump such as a re-estimated normal makes. The strain is
  // carried with the normal, so the tension stays E e, now along y. Resolving the stored
  // global strain in the new frame instead (thesis §5.4.2 alone) loses (1 + ν) e dθ² per
  // step, and in the jump reads the thickness strain −ν e as the membrane strain.
  for (const int steps : {1000, 1}) {
    Membrane<2> m(Kinematics::plane_strain, 1.0, E, nu, MembraneLaw::uniaxial, false);
    Sym<2> strain;
    strain << 1e-3, -nu * 1e-3, -nu * 1e-3, 0.0;
    Particles<2> p = one_point<2>(m, Vec2(1, 0), Vec2(0, 1), strain);
    update<2>(m, p, Mat<2>::Zero(), 0.0);  // the first update records the frame
    for (int k = 1; k <= steps; ++k) {
      const double a = 0.5 * std::numbers::pi * k / steps;
      p.named<Vec2>("tangent")[0] = Vec2(std::cos(a), std::sin(a));
      p.named<Vec2>("normal")[0] = Vec2(-std::sin(a), std::cos(a));
      update<2>(m, p, Mat<2>::Zero(), 0.0);
    }
    EXPECT_NEAR(p.stress[0][1], E * 1e-3, 1e-9 * E) << steps << " steps";
    EXPECT_NEAR(p.stress[0][0], 0.0, 1e-9 * E) << steps << " steps";
  }
}

TEST(MembraneLaw, ASurfaceKeepsItsStrainWhenItsNormalFlipsOrJumps) {
  // Biaxial strain (2e-3 along x, 1e-3 along y) of a membrane in the plane z = 0.
  Membrane<3> m(Kinematics::solid, 1.0, E, nu, MembraneLaw::plane_stress, false);
  Sym<3> strain = Sym<3>::Zero();
  strain[0] = 2e-3;
  strain[1] = 1e-3;
  strain[2] = -nu / (1 - nu) * 3e-3;
  Particles<3> p = one_point<3>(m, Vec3(1, 0, 0), Vec3(0, 0, 1), strain);
  update<3>(m, p, Mat<3>::Zero(), 0.0);
  const double s_x = E / (1 - nu * nu) * (2e-3 + nu * 1e-3);
  const double s_y = E / (1 - nu * nu) * (1e-3 + nu * 2e-3);
  EXPECT_NEAR(p.stress[0][0], s_x, 1e-9 * E);
  // The opposite normal is the same plane: nothing changes.
  p.named<Vec3>("normal")[0] = Vec3(0, 0, -1);
  p.named<Vec3>("tangent")[0] = Vec3(0, 1, 0);
  update<3>(m, p, Mat<3>::Zero(), 0.0);
  EXPECT_NEAR(p.stress[0][0], s_x, 1e-9 * E);
  EXPECT_NEAR(p.stress[0][1], s_y, 1e-9 * E);
  // A jump of 60° about x: the strain turns with the plane (y → (0, cos, sin)).
  const double a = std::numbers::pi / 3;
  p.named<Vec3>("normal")[0] = Vec3(0, -std::sin(a), std::cos(a));
  p.named<Vec3>("tangent")[0] = Vec3(1, 0, 0);
  update<3>(m, p, Mat<3>::Zero(), 0.0);
  const Mat3 stress = to_mat3<3>(p.stress[0]);
  const Vec3 y_turned(0, std::cos(a), std::sin(a));
  EXPECT_NEAR(stress(0, 0), s_x, 1e-9 * E);
  EXPECT_NEAR(y_turned.dot(stress * y_turned), s_y, 1e-9 * E);
  EXPECT_NEAR((stress * Vec3(0, -std::sin(a), std::cos(a))).norm(), 0.0, 1e-9 * E);
}

TEST(MembraneLaw, NormalTransportIsTheSmallestRotation) {
  const Vec3 from = Vec3(1, 2, 2) / 3.0, to = Vec3(2, -1, 2) / 3.0;
  for (const Vec3& target : {to, Vec3(-to)}) {
    const Mat3 R = normal_transport(from, target);
    EXPECT_NEAR((R * from - to).norm(), 0.0, 1e-14);  // to whichever of ±target is nearer
    EXPECT_NEAR((R.transpose() * R - Mat3::Identity()).norm(), 0.0, 1e-14);
    EXPECT_NEAR((R * from.cross(to) - from.cross(to)).norm(), 0.0, 1e-14);  // about from × to
  }
  const Mat3 R2 = normal_transport(Vec2(1, 0), Vec2(-0.6, -0.8));
  EXPECT_NEAR((R2.topLeftCorner<2, 2>() * Vec2(1, 0) - Vec2(0.6, 0.8)).norm(), 0.0, 1e-14);
  EXPECT_EQ(R2(2, 2), 1.0);  // the out-of-plane direction stays
}

}  // namespace
}  // namespace pellicle
