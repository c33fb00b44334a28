// The validation problems (src/pellicle/validation/) at fast resolution: every check must
// lie in its accepted range. `pellicle validate --full` runs the same problems refined.
//   bar-vibration    free–free bar period within 1% of 2L/c, every kernel, 2D and 3D
//   cylinder-radial  axisymmetric radial modes: reversal times within 1% of the period
//   two-disks        Sulsky et al. 1994: APIC energy within 2% through the collision
//   two-bars-stick   IJNME 1999 Fig. 18: the bars stick with the single velocity field
//   spring-mass      IJNME §3.1.1: period 1%, amplitude 2%, y(t) within the drift those allow;
//                    stable at 1.6, unstable at 1.7 Δt_crit
//   string-slack     IJNME §3.2: free fall, tension and free-flight times within 10%; peak
//                    strain energy within 5% of the falling mass's, ½ k δ² = m g (s + δ)
//   pendulum         IJNME §3.1.2: θ(t) against bar elements, error below atan(h/L) (the end
//                    point misplaced by a cell) and falling with refinement
//   drum             3D membrane: fundamental period within 3%, error falling with refinement
//   sphere-breathing 3D curved membrane: breathing period within 2%
//   normals-accuracy every frame estimator on whole curves and surfaces
//   sod              thesis §4.1: shock position, pressure ratio, speed within 3%; L1 errors
//                    below 3h × the exact profile's total variation, and falling
//   strong-shock     held-out tube, pressure ratio 100, 400 cells, APIC and FLIP: post-shock
//                    density within 2%, shock position 3%, L1 density as sod's, energy 1%
//   gas-expansion    thesis §4.2: energy within 1%, falling with Δt; edge below escape speed
//   piston-container thesis §6.1: period within 2% of the frequency equation, two masses
//   normal-methods-fsi thesis §7.5, §7.7: connectivity and pca frames hold the gas in the
//                    expanding cylinder and (to t = 1) the dog-bone; the quadratic colour does not
//   two-bars-release IJNME §4.2: with contact-release the bars part; difference converges
//   disks-wire       IJNME §4.3: the disks pinch the wire, never cross it, and part from it,
//                    disk I to the left and disk II to the right
//   offset-disks     IJNME §4.4: clockwise spin while pinching, counter-clockwise after
//   ball-and-net     thesis §5.9, A.1.6: cell-width net: release near t = 2.8 at −0.7 (15%),
//                    over twice as fast as the single field, the net clear of the wall
//   dogbone          thesis §6.2: the gas-filled dog-bone holds its gas, keeps its energy
//                    within 5%, ends with tension = p R (10%) and the thesis's radii (5%, 2%)
//   airbag           thesis §6.3: Cyl-200 onto the pre-inflated bag: gas held, the probe
//                    stops in the bag and rebounds no faster than it came, energy kept
//   friction-block   Coulomb friction: block on an incline within 3% of g(sin θ − μ cos θ)
//   surface-movement Suchde & Kuhnert §3.7.1–2: first- vs second-order movement of a rotating
//                    quarter sphere; the deforming hemisphere with management converging in Δt
//   surface-point-addition §3.7.4: midway placement below half the circumcentre's error,
//                    faster than h²; the circumcentre's error second order
//   curvature-flow   §4.2.3: a sphere under mean-curvature flow, R(t) within 2% of
//                    sqrt(R0² − 2t) until R = 0.3 R0, a circle in 2D and a cylinder
//                    (sqrt(R0² − t), the middle of an open tube); an ellipsoid
//                    under averaged flow keeps
//                    its volume within 1% and is a sphere within 2% at t = 2.5
//   joining-spheres  §3.7.3: non-penetration keeps the spheres within |v|Δt + r_min h of
//                    the plane where they meet (h at the disc's rim); delete joins them into
//                    one chamber enclosing the union
//                    (within the seam band's share); merge joins them once the gap < r_min h
//   dumbbell-pinch   §4.2.3: the neck pinches between t = 0.04 (cylinder law) and 0.08 and
//                    the run goes on with two closed surfaces
//   torus-genus      §4.2.3: under averaged flow the hole closes before t = 10 (paper: 7)
//                    and the run goes on as one chamber
//   wave-collapse    §4.2.4: the wave on a creature that eq 52 flattens runs to t = 1.2
//                    through folds and self-contact deletions; ∮ Dφ/Dt dA kept within 2 %
//                    until the first deletion
//   surface-cdr-sphere §4.2.1: Tables 2 and 3 (errors within 1.5×, orders within 0.2)
//   surface-wave-sphere §4.2.4: Table 4 (same tolerances)
//   surface-half-pipe §4.2.2: ∫ φ dA kept within 1 % while the half pipe twists to t = 2
//   laplace-spectrum  −Δ_M eigenvalues on the sphere (l(l+1)) and a torus within 1%
#include <gtest/gtest.h>

#include <cstdio>

#include "pellicle/validation/problem.hpp"

namespace pellicle::validation {
namespace {

void expect_all_checks_pass(const std::string& name) {
  const Problem* problem = find_problem(name);
  ASSERT_NE(problem, nullptr);
  const Outcome outcome = problem->run(Resolution::fast);
  ASSERT_FALSE(outcome.checks.empty());
  for (const auto& check : outcome.checks) {
    std::printf("%s: %s\n", name.c_str(), check.describe().c_str());
    EXPECT_TRUE(check.passed()) << check.describe();
  }
}

TEST(Validation, Dogbone) {
  expect_all_checks_pass("dogbone");
}
TEST(Validation, Airbag) {
  expect_all_checks_pass("airbag");
}
TEST(Validation, BarVibration) {
  expect_all_checks_pass("bar-vibration");
}
TEST(Validation, CylinderRadialVibration) {
  expect_all_checks_pass("cylinder-radial");
}
TEST(Validation, TwoDisks) {
  expect_all_checks_pass("two-disks");
}
TEST(Validation, TwoBarsStick) {
  expect_all_checks_pass("two-bars-stick");
}
TEST(Validation, SpringMass) {
  expect_all_checks_pass("spring-mass");
}
TEST(Validation, Stability) {
  expect_all_checks_pass("stability");
}
TEST(Validation, StringWithSlack) {
  expect_all_checks_pass("string-slack");
}
TEST(Validation, Pendulum) {
  expect_all_checks_pass("pendulum");
}
TEST(Validation, Drum) {
  expect_all_checks_pass("drum");
}
TEST(Validation, SphereBreathing) {
  expect_all_checks_pass("sphere-breathing");
}
TEST(Validation, NormalMethodsOnGasFilledMembranes) {
  expect_all_checks_pass("normal-methods-fsi");
}
TEST(Validation, SodShockTube) {
  expect_all_checks_pass("sod");
}
TEST(Validation, StrongShockTube) {
  expect_all_checks_pass("strong-shock");
}
TEST(Validation, GasExpansion) {
  expect_all_checks_pass("gas-expansion");
}
TEST(Validation, PistonContainer) {
  expect_all_checks_pass("piston-container");
}
TEST(Validation, TwoBarsRelease) {
  expect_all_checks_pass("two-bars-release");
}
TEST(Validation, DisksWire) {
  expect_all_checks_pass("disks-wire");
}
TEST(Validation, OffsetDisks) {
  expect_all_checks_pass("offset-disks");
}
TEST(Validation, BallAndNet) {
  expect_all_checks_pass("ball-and-net");
}
TEST(Validation, FrictionBlock) {
  expect_all_checks_pass("friction-block");
}
TEST(Validation, NormalsAccuracy) {
  expect_all_checks_pass("normals-accuracy");
}

TEST(Validation, SurfaceMovement) {
  expect_all_checks_pass("surface-movement");
}
TEST(Validation, SurfacePointAddition) {
  expect_all_checks_pass("surface-point-addition");
}
TEST(Validation, CurvatureFlows) {
  expect_all_checks_pass("curvature-flow");
}

TEST(Validation, JoiningSpheres) {
  expect_all_checks_pass("joining-spheres");
}

TEST(Validation, DumbbellPinch) {
  expect_all_checks_pass("dumbbell-pinch");
}

TEST(Validation, TorusGenus) {
  expect_all_checks_pass("torus-genus");
}
TEST(Validation, WaveCollapse) {
  expect_all_checks_pass("wave-collapse");
}
TEST(Validation, SurfaceCdrSphere) {
  expect_all_checks_pass("surface-cdr-sphere");
}
TEST(Validation, SurfaceWaveSphere) {
  expect_all_checks_pass("surface-wave-sphere");
}
TEST(Validation, SurfaceHalfPipe) {
  expect_all_checks_pass("surface-half-pipe");
}
TEST(Validation, LaplaceSpectrum) {
  expect_all_checks_pass("laplace-spectrum");
}
TEST(Validation, EveryProblemHasAName) {
  for (const auto& p : problems()) {
    EXPECT_EQ(find_problem(p.name), &p);
    EXPECT_FALSE(p.source.empty()) << p.name;
  }
}

}  // namespace
}  // namespace pellicle::validation
