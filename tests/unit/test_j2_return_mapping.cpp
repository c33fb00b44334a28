// J2 plasticity with linear isotropic hardening at a point (docs/theory/plasticity.md): the
// uniaxial and pure-shear curves against their closed forms, equi-biaxial plane stress, the
// plane-stress return against the 3D return with its thickness strain, plane strain and
// axisymmetry against 3D, consistency after plastic steps, perfect plasticity, and the energy
// bookkeeping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "pellicle/mpm/materials/j2_return_mapping.hpp"
#include "pellicle/mpm/materials/kinematics.hpp"

namespace pellicle {
namespace {

// Steel-like constants in MPa: ε_y = σ_y0/E = 1.25e-3, E_t = E H/(E + H) ≈ 1980.2.
constexpr J2Constants kSteel{200.0e3, 0.3, 250.0, 2000.0};
constexpr J2Constants kPerfect{200.0e3, 0.3, 250.0, 0.0};

template <int D>
J2State<D> zero_state() {
  return {Sym<D>::Zero(), 0.0};
}

// --- Uniaxial stress, strain-driven ------------------------------------------------------

// One step with axial increment dexx and the lateral increment a (3D: Δε_yy = Δε_zz = a;
// plane stress: Δε_yy = a, Δε_zz from the return) found by bisection so that σ_yy = 0.
// σ_yy grows with a; the bracket [−w, w] is widened until it changes sign.
template <int D>
J2State<D> uniaxial_step(const J2State<D>& old, double dexx, const J2Constants& c,
                         Kinematics kinematics, double* lateral = nullptr,
                         double* thickness = nullptr) {
  Sym<D> de_out;
  const auto run = [&](double a, J2State<D>* out) {
    Sym<D> de = Sym<D>::Zero();
    de[0] = dexx;
    de[1] = a;
    if (D == 3) de[2] = a;
    const J2State<D> s = j2_update<D>(old, de, c, kinematics);
    if (out) {
      *out = s;
      de_out = de;
    }
    return s.stress[1];
  };
  double w = std::max(std::abs(dexx), 1e-300);
  for (int k = 0; k < 60 && !(run(-w, nullptr) < 0.0 && run(w, nullptr) > 0.0); ++k) w *= 2.0;
  double lo = -w, hi = w;
  for (int k = 0; k < 300; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (run(mid, nullptr) < 0.0 ? lo : hi) = mid;
  }
  const double a = std::abs(run(lo, nullptr)) < std::abs(run(hi, nullptr)) ? lo : hi;
  J2State<D> result;
  run(a, &result);
  if (lateral) *lateral = a;
  if (thickness) *thickness = de_out[2];
  return result;
}

// Exact uniaxial state: strain ε, stress σ, equivalent plastic strain ε̄p (P18).
struct Uniaxial {
  double eps, sigma, ep;
};

// Exact state after monotone straining from `start` to ε (either direction): elastic with
// slope E until |σ| reaches σ_y(ε̄p), then slope E_t = EH/(E+H) with dε̄p = E/(E+H) |dε|.
Uniaxial exact_uniaxial(const Uniaxial& start, double eps, const J2Constants& c) {
  const double E = c.young, H = c.hardening;
  const double dir = eps >= start.eps ? 1.0 : -1.0;
  const double limit = dir * j2_yield_stress(c, start.ep);
  const double elastic_end = start.eps + (limit - start.sigma) / E;
  if ((eps - elastic_end) * dir <= 0.0) return {eps, start.sigma + E * (eps - start.eps), start.ep};
  const double beyond = eps - elastic_end;
  return {eps, limit + E * H / (E + H) * beyond, start.ep + E / (E + H) * std::abs(beyond)};
}

// Load to 8 ε_y, unload to zero stress, reload to 14 ε_y, reverse into compressive yield.
// Returns the segment end strains (from the exact curve) with the exact states there.
std::vector<Uniaxial> uniaxial_path(const J2Constants& c) {
  const double ey = c.yield_stress / c.young;
  std::vector<Uniaxial> ends{{0.0, 0.0, 0.0}};
  const auto go = [&](double eps) { ends.push_back(exact_uniaxial(ends.back(), eps, c)); };
  go(8.0 * ey);
  go(ends.back().eps - ends.back().sigma / c.young);
  go(14.0 * ey);
  go(ends.back().eps - 2.0 * ends.back().sigma / c.young - 5.0 * ey);
  return ends;
}

// Drives the path with, in each segment, the given fractions of the segment as step ends,
// checking every step end against the exact curve to 1e-8 relative.
template <int D>
void check_uniaxial(const J2Constants& c, Kinematics kinematics,
                    const std::vector<std::vector<double>>& fractions) {
  const std::vector<Uniaxial> ends = uniaxial_path(c);
  const double ey = c.yield_stress / c.young;
  J2State<D> state = zero_state<D>();
  double eps = 0.0;
  for (std::size_t seg = 0; seg + 1 < ends.size(); ++seg) {
    for (double f : fractions[seg]) {
      const double target = ends[seg].eps + f * (ends[seg + 1].eps - ends[seg].eps);
      double lateral = 0.0, thickness = 0.0;
      state = uniaxial_step<D>(state, target - eps, c, kinematics, &lateral, &thickness);
      eps = target;
      const Uniaxial exact = exact_uniaxial(ends[seg], eps, c);
      SCOPED_TRACE(testing::Message() << "segment " << seg << " ε/ε_y " << eps / ey);
      EXPECT_NEAR(state.stress[0], exact.sigma,
                  1e-8 * std::max(std::abs(exact.sigma), c.yield_stress));
      EXPECT_NEAR(state.plastic_strain, exact.ep, 1e-8 * std::max(exact.ep, ey));
      if (c.hardening > 0.0 && seg == 0 && exact.ep > 0.0) {  // ε̄p = (σ − σ_y0)/H
        EXPECT_NEAR(state.plastic_strain, (state.stress[0] - c.yield_stress) / c.hardening,
                    1e-8 * exact.ep);
      }
      for (int k = 1; k < kSymComponents<D>; ++k)
        EXPECT_NEAR(state.stress[k], 0.0, 1e-12 * c.yield_stress);
      if (kinematics == Kinematics::plane_stress) {
        // Isotropy: the thickness strain of uniaxial stress equals the lateral strain.
        EXPECT_NEAR(thickness, lateral, 1e-10 * std::abs(lateral));
      }
    }
  }
}

std::vector<std::vector<double>> many_small_steps(int n) {
  std::vector<double> f;
  for (int k = 1; k <= n; ++k) f.push_back(double(k) / n);
  return {f, f, f, f};
}

// Few large steps, several of which cross the yield point inside the step.
const std::vector<std::vector<double>> kLargeSteps{{0.05, 0.6, 1.0}, {1.0}, {0.5, 1.0}, {1.0}};

TEST(J2ReturnMapping, UniaxialStress3DSmallSteps) {
  check_uniaxial<3>(kSteel, Kinematics::solid, many_small_steps(200));
}

TEST(J2ReturnMapping, UniaxialStress3DLargeSteps) {
  check_uniaxial<3>(kSteel, Kinematics::solid, kLargeSteps);
}

TEST(J2ReturnMapping, UniaxialStressPlaneStressSmallSteps) {
  check_uniaxial<2>(kSteel, Kinematics::plane_stress, many_small_steps(200));
}

TEST(J2ReturnMapping, UniaxialStressPlaneStressLargeSteps) {
  check_uniaxial<2>(kSteel, Kinematics::plane_stress, kLargeSteps);
}

// The named features of the curve on a fine path: slope E below σ_y0, slope E_t above, slope E
// when unloading from the peak, reloading elastic up to the peak stress and plastic beyond.
TEST(J2ReturnMapping, UniaxialStress3DSlopesAndReloadYield) {
  const J2Constants& c = kSteel;
  const double E = c.young, Et = E * c.hardening / (E + c.hardening);
  const double ey = c.yield_stress / E;
  const std::vector<Uniaxial> ends = uniaxial_path(c);
  const double peak = ends[1].sigma, peak_ep = ends[1].ep;

  J2State<3> s = zero_state<3>();
  // Load: 0.9 ε_y in one elastic step, up to ε_y, then plastic steps.
  J2State<3> next = uniaxial_step<3>(s, 0.9 * ey, c, Kinematics::solid);
  EXPECT_NEAR(next.stress[0], E * 0.9 * ey, 1e-8 * c.yield_stress);
  EXPECT_EQ(next.plastic_strain, 0.0);
  s = uniaxial_step<3>(next, 0.1 * ey, c, Kinematics::solid);
  EXPECT_NEAR(s.stress[0], c.yield_stress, 1e-8 * c.yield_stress);
  EXPECT_NEAR(s.plastic_strain, 0.0, 1e-8 * ey);
  const double de = 7.0 * ey / 50;
  for (int k = 0; k < 50; ++k) {
    next = uniaxial_step<3>(s, de, c, Kinematics::solid);
    EXPECT_NEAR((next.stress[0] - s.stress[0]) / de, Et, 1e-8 * Et);
    s = next;
  }
  EXPECT_NEAR(s.stress[0], peak, 1e-8 * peak);
  EXPECT_NEAR(s.plastic_strain, peak_ep, 1e-8 * peak_ep);
  const double reached_ep = s.plastic_strain;
  // Unload by half the peak stress: slope E, no plastic flow.
  const double back = -0.5 * peak / E;
  next = uniaxial_step<3>(s, back, c, Kinematics::solid);
  EXPECT_NEAR((next.stress[0] - s.stress[0]) / back, E, 1e-8 * E);
  EXPECT_EQ(next.plastic_strain, s.plastic_strain);
  // Reload to just below the peak strain: still elastic, stress just below the peak.
  s = uniaxial_step<3>(next, -back - 1e-3 * ey, c, Kinematics::solid);
  EXPECT_EQ(s.plastic_strain, reached_ep);
  EXPECT_NEAR(s.stress[0], peak - 1e-3 * ey * E, 1e-8 * peak);
  // Past it: yields at the new yield stress σ_y0 + H ε̄p = peak, slope E_t beyond.
  next = uniaxial_step<3>(s, 2e-3 * ey, c, Kinematics::solid);
  EXPECT_GT(next.plastic_strain, reached_ep);
  EXPECT_NEAR(next.plastic_strain - reached_ep, E / (E + c.hardening) * 1e-3 * ey,
              1e-8 * 1e-3 * ey);
  EXPECT_NEAR(next.stress[0], peak + Et * 1e-3 * ey, 1e-8 * peak);
}

// --- Pure shear ----------------------------------------------------------------------------

// Exact pure shear (P19): τ = 2G γ/2 up to τ_y = σ_y/√3, then slope 2GH/(3G + H) in ε_xy.
double exact_shear(double exy, const J2Constants& c) {
  const double G = c.shear(), ty = c.yield_stress / std::sqrt(3.0), ey = ty / (2.0 * G);
  if (exy <= ey) return 2.0 * G * exy;
  return ty + 2.0 * G * c.hardening / (3.0 * G + c.hardening) * (exy - ey);
}

TEST(J2ReturnMapping, PureShear3DYieldsAtSigmaYOverRoot3) {
  for (const J2Constants& c : {kSteel, kPerfect}) {
    const double G = c.shear(), ty = c.yield_stress / std::sqrt(3.0), ey = ty / (2.0 * G);
    // Just below and just above the yield strain, in one step from rest.
    for (double f : {1.0 - 1e-6, 1.0 + 1e-6}) {
      Sym<3> de = Sym<3>::Zero();
      de[5] = f * ey;
      const J2State<3> s = j2_update<3>(zero_state<3>(), de, c, Kinematics::solid);
      EXPECT_NEAR(s.stress[5], exact_shear(f * ey, c), 1e-12 * ty);
      if (f < 1.0) {
        EXPECT_EQ(s.plastic_strain, 0.0);
      } else {
        EXPECT_GT(s.plastic_strain, 0.0);
      }
    }
    // Small steps to 6 ε_y, then one large step to 12 ε_y, in the yz component.
    J2State<3> s = zero_state<3>();
    double exy = 0.0;
    std::vector<double> targets;
    for (int k = 1; k <= 120; ++k) targets.push_back(6.0 * ey * k / 120);
    targets.push_back(12.0 * ey);
    for (double t : targets) {
      Sym<3> de = Sym<3>::Zero();
      de[3] = t - exy;
      exy = t;
      s = j2_update<3>(s, de, c, Kinematics::solid);
      const double tau = exact_shear(exy, c);
      EXPECT_NEAR(s.stress[3], tau, 1e-8 * ty);
      for (int k : {0, 1, 2, 4, 5}) EXPECT_EQ(s.stress[k], 0.0);
      // Yield stress in shear: q = √3 τ = σ_y(ε̄p) once plastic.
      if (exy > ey) {
        EXPECT_NEAR(std::sqrt(3.0) * s.stress[3], j2_yield_stress(c, s.plastic_strain), 1e-10 * ty);
      }
      if (c.hardening == 0.0 && exy >= ey) {
        EXPECT_NEAR(s.stress[3], ty, 1e-12 * ty);
      }
    }
  }
}

// --- Plane strain and axisymmetry against 3D ----------------------------------------------

// Random velocity gradients with spin, applied as the caller does: Jaumann rotation first,
// then the return with Δε = Δt sym(L) (and the hoop increment in Δε_zz).
TEST(J2ReturnMapping, PlaneStrainAndAxisymmetryMatch3D) {
  for (Kinematics kinematics : {Kinematics::plane_strain, Kinematics::axisymmetric}) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const J2Constants& c = kSteel;
    const double rate = 1.5 * c.yield_stress / c.young, dt = 1.0;
    J2State<2> s2 = zero_state<2>();
    J2State<3> s3 = zero_state<3>();
    int plastic_steps = 0;
    for (int step = 0; step < 200; ++step) {
      Mat<2> L;
      L << u(rng), u(rng), u(rng), u(rng);
      L *= rate;
      const double hoop = kinematics == Kinematics::axisymmetric ? rate * u(rng) : 0.0;
      Mat3 L3 = Mat3::Zero();
      L3.topLeftCorner<2, 2>() = L;
      L3(2, 2) = hoop;

      s2.stress = jaumann_rotate<2>(s2.stress, L, dt);
      s3.stress = jaumann_rotate<3>(s3.stress, L3, dt);
      Sym<2> de2 = strain_increment<2>(L, hoop, dt);
      Sym<3> de3 = strain_increment<3>(L3, 0.0, dt);
      const double ep_before = s2.plastic_strain;
      s2 = j2_update<2>(s2, de2, c, kinematics);
      s3 = j2_update<3>(s3, de3, c, Kinematics::solid);
      plastic_steps += s2.plastic_strain > ep_before;

      const double scale = 1e-12 * c.yield_stress;
      EXPECT_NEAR(s2.stress[0], s3.stress[0], scale);
      EXPECT_NEAR(s2.stress[1], s3.stress[1], scale);
      EXPECT_NEAR(s2.stress[2], s3.stress[2], scale);
      EXPECT_NEAR(s2.stress[3], s3.stress[5], scale);
      EXPECT_NEAR(s3.stress[3], 0.0, scale);
      EXPECT_NEAR(s3.stress[4], 0.0, scale);
      EXPECT_NEAR(s2.plastic_strain, s3.plastic_strain, 1e-12 * std::max(s3.plastic_strain, 1e-3));
    }
    EXPECT_GT(plastic_steps, 50);  // the comparison covered plastic steps
  }
}

// --- Plane stress ------------------------------------------------------------------------

// The plane-stress step is the 3D backward-Euler step with the thickness strain it returns
// (P15): replaying that full increment through the 3D return must give the same in-plane
// stress and ε̄p with σ_zz = 0. Non-proportional random paths, three Poisson's ratios.
TEST(J2ReturnMapping, PlaneStressReturnIs3DReturnWithItsThicknessStrain) {
  for (double nu : {-0.2, 0.3, 0.49}) {
    for (double hardening : {2000.0, 0.0, 5.0e4}) {
      const J2Constants c{200.0e3, nu, 250.0, hardening};
      std::mt19937 rng(11);
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      const double rate = 2.0 * c.yield_stress / c.young;
      J2State<2> s = zero_state<2>();
      int plastic_steps = 0;
      for (int step = 0; step < 200; ++step) {
        Mat<2> L;
        L << u(rng), u(rng), u(rng), u(rng);
        L *= rate;
        J2State<2> old = s;
        old.stress = jaumann_rotate<2>(s.stress, L, 1.0);
        Sym<2> de = strain_increment<2>(L, 0.0, 1.0);
        s = j2_update<2>(old, de, c, Kinematics::plane_stress);
        plastic_steps += s.plastic_strain > old.plastic_strain;

        J2State<3> old3{Sym<3>::Zero(), old.plastic_strain};
        old3.stress << old.stress[0], old.stress[1], 0.0, 0.0, 0.0, old.stress[3];
        Sym<3> de3;
        de3 << de[0], de[1], de[2], 0.0, 0.0, de[3];
        const J2State<3> s3 = j2_update<3>(old3, de3, c, Kinematics::solid);

        const double scale = 1e-12 * c.yield_stress;
        SCOPED_TRACE(testing::Message() << "nu " << nu << " H " << hardening << " step " << step);
        EXPECT_EQ(s.stress[2], 0.0);
        EXPECT_NEAR(s3.stress[2], 0.0, scale);  // σ_zz = 0 under the 3D law
        EXPECT_NEAR(s3.stress[0], s.stress[0], scale);
        EXPECT_NEAR(s3.stress[1], s.stress[1], scale);
        EXPECT_NEAR(s3.stress[5], s.stress[3], scale);
        EXPECT_NEAR(s3.plastic_strain, s.plastic_strain, 1e-12 * std::max(s.plastic_strain, 1e-3));
      }
      EXPECT_GT(plastic_steps, 50);
    }
  }
}

// Very large steps (trial q up to ~10³ σ_y), Poisson's ratios from −0.5 to 0.499, hardening
// from 0 to 5E: the safeguarded Newton solve still ends on the yield surface, and the 3D replay
// agrees to round-off.
TEST(J2ReturnMapping, PlaneStressLargeStepsConverge) {
  for (double nu : {-0.5, 0.0, 0.3, 0.499}) {
    for (double hardening : {0.0, 2000.0, 1.0e6}) {
      const J2Constants c{200.0e3, nu, 250.0, hardening};
      std::mt19937 rng(3);
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      for (int trial = 0; trial < 50; ++trial) {
        const double size = std::pow(10.0, 3.0 * (u(rng) + 1.0) / 2.0);  // 1 … 10³
        Sym<2> de;
        de << u(rng), u(rng), 0.0, u(rng);
        de *= size * c.yield_stress / c.young;
        const J2State<2> old{Sym<2>::Zero(), 0.0};
        const J2State<2> s = j2_update<2>(old, de, c, Kinematics::plane_stress);
        const double q = von_mises_stress<2>(s.stress);
        SCOPED_TRACE(testing::Message() << "nu " << nu << " H " << hardening << " size " << size);
        ASSERT_TRUE(std::isfinite(q) && std::isfinite(s.plastic_strain) && std::isfinite(de[2]));
        if (s.plastic_strain > 0.0) {
          EXPECT_NEAR(q, j2_yield_stress(c, s.plastic_strain), 1e-10 * q);
        }
        J2State<3> old3{Sym<3>::Zero(), 0.0};
        Sym<3> de3;
        de3 << de[0], de[1], de[2], 0.0, 0.0, de[3];
        const J2State<3> s3 = j2_update<3>(old3, de3, c, Kinematics::solid);
        // The replay's trial stress reaches ~K|tr Δε|, which the 3D return cancels in σ_zz, so
        // round-off there is relative to the trial (K/G ≈ 500 at ν = 0.499).
        Sym<3> trial3 = 2.0 * c.shear() * de3;
        trial3.head<3>().array() += c.lambda() * trace<3>(de3);
        const double scale = 1e-12 * std::max(trial3.cwiseAbs().maxCoeff(), c.yield_stress);
        EXPECT_NEAR(s3.stress[2], 0.0, scale);
        EXPECT_NEAR(s3.stress[0], s.stress[0], scale);
        EXPECT_NEAR(s3.stress[1], s.stress[1], scale);
        EXPECT_NEAR(s3.stress[5], s.stress[3], scale);
        EXPECT_NEAR(s3.plastic_strain, s.plastic_strain, 1e-10 * s.plastic_strain + 1e-300);
      }
    }
  }
}

// Equi-biaxial plane stress (Δε_xx = Δε_yy): σ_xx = σ_yy = σ = q; elastic slope E/(1 − ν),
// plastic slope 2EH/(E + 2H(1 − ν)); thickness strain ε_zz = −2νσ/E − ε̄p (P20). Exercises the
// in-plane mean-stress part of the plane-stress return, where φ is nonlinear in x.
TEST(J2ReturnMapping, PlaneStressEquibiaxial) {
  for (const J2Constants& c : {kSteel, kPerfect}) {
    const double E = c.young, nu = c.poisson, H = c.hardening;
    const double ey = c.yield_stress * (1.0 - nu) / E;  // biaxial yield strain
    const auto exact_sigma = [&](double e) {
      if (e <= ey) return E / (1.0 - nu) * e;
      return c.yield_stress + 2.0 * E * H / (E + 2.0 * H * (1.0 - nu)) * (e - ey);
    };
    for (const std::vector<double>& ends :
         {std::vector<double>{0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0},
          std::vector<double>{0.7, 8.0}}) {
      J2State<2> s = zero_state<2>();
      double e = 0.0, ezz = 0.0;
      for (double end : ends) {
        Sym<2> de;
        de << end * ey - e, end * ey - e, 0.0, 0.0;
        e = end * ey;
        s = j2_update<2>(s, de, c, Kinematics::plane_stress);
        ezz += de[2];
        const double sigma = exact_sigma(e);
        // ε_xx = (1 − ν)σ/E + ε̄p/2 (the flow direction of equi-biaxial stress is
        // (½, ½, −1) in (xx, yy, zz)), so ε̄p = 2(ε − (1 − ν)σ/E).
        const double ep_exact = 2.0 * (e - sigma * (1.0 - nu) / E);
        EXPECT_NEAR(s.stress[0], sigma, 1e-8 * sigma);
        EXPECT_NEAR(s.stress[1], sigma, 1e-8 * sigma);
        EXPECT_EQ(s.stress[2], 0.0);
        EXPECT_NEAR(s.plastic_strain, ep_exact, 1e-8 * std::max(ep_exact, ey));
        EXPECT_NEAR(ezz, -2.0 * nu * sigma / E - ep_exact, 1e-8 * ey);
      }
    }
  }
}

// --- Consistency and the volumetric response, every kinematics ---------------------------

template <int D>
void check_consistency(Kinematics kinematics, const J2Constants& c) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  J2State<D> s = zero_state<D>();
  int plastic_steps = 0;
  for (int step = 0; step < 300; ++step) {
    Sym<D> de;
    for (int k = 0; k < kSymComponents<D>; ++k) de[k] = u(rng);
    if (kinematics == Kinematics::plane_strain) de[2] = 0.0;
    // Mostly modest steps, every tenth a large one.
    de *= (step % 10 == 9 ? 20.0 : 1.0) * c.yield_stress / c.young;
    const J2State<D> old = s;
    s = j2_update<D>(old, de, c, kinematics);
    const double q = von_mises_stress<D>(s.stress);
    const double sy = j2_yield_stress(c, s.plastic_strain);
    SCOPED_TRACE(testing::Message() << "step " << step);
    EXPECT_GE(s.plastic_strain, old.plastic_strain);
    if (s.plastic_strain > old.plastic_strain) {
      ++plastic_steps;
      EXPECT_NEAR(q, sy, 1e-10 * sy);  // (P10) / (P14)
    } else {
      EXPECT_LE(q, sy * (1.0 + 1e-14));
    }
    // Plastic flow is deviatoric: Δ tr σ = 3K tr Δε (with the thickness strain in plane stress).
    EXPECT_NEAR(trace<D>(s.stress) - trace<D>(old.stress), 3.0 * c.bulk() * trace<D>(de),
                1e-10 * std::max(sy, std::abs(trace<D>(s.stress))));
  }
  EXPECT_GT(plastic_steps, 100);
}

TEST(J2ReturnMapping, ConsistencyAfterPlasticSteps) {
  for (const J2Constants& c : {kSteel, kPerfect}) {
    check_consistency<3>(Kinematics::solid, c);
    check_consistency<2>(Kinematics::plane_strain, c);
    check_consistency<2>(Kinematics::axisymmetric, c);
    check_consistency<2>(Kinematics::plane_stress, c);
  }
}

// --- Perfect plasticity ---------------------------------------------------------------------

TEST(J2ReturnMapping, PerfectPlasticity) {
  // The uniaxial curve with H = 0: flat at σ_y0, unloading with slope E, reverse yield at −σ_y0.
  check_uniaxial<3>(kPerfect, Kinematics::solid, many_small_steps(50));
  check_uniaxial<3>(kPerfect, Kinematics::solid, kLargeSteps);
  check_uniaxial<2>(kPerfect, Kinematics::plane_stress, many_small_steps(50));
  check_uniaxial<2>(kPerfect, Kinematics::plane_stress, kLargeSteps);
  // A huge step stays finite and on the yield surface.
  for (Kinematics kinematics : {Kinematics::plane_strain, Kinematics::plane_stress}) {
    Sym<2> de;
    de << 0.3, -0.1, 0.0, 0.2;
    const J2State<2> s = j2_update<2>(zero_state<2>(), de, kPerfect, kinematics);
    EXPECT_TRUE(std::isfinite(s.plastic_strain));
    EXPECT_NEAR(von_mises_stress<2>(s.stress), kPerfect.yield_stress,
                1e-10 * kPerfect.yield_stress);
  }
}

// --- Energy bookkeeping ----------------------------------------------------------------------

TEST(J2ReturnMapping, ElasticEnergyDensityIsHalfStressTimesStrain) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const J2Constants c{200.0e3, 0.3, 1.0e30, 0.0};  // never yields
  for (int trial = 0; trial < 10; ++trial) {
    Sym<3> e3;
    for (int k = 0; k < 6; ++k) e3[k] = 1e-3 * u(rng);
    Sym<3> de3 = e3;
    const J2State<3> s3 = j2_update<3>(zero_state<3>(), de3, c, Kinematics::solid);
    const double w3 = 0.5 * contract<3>(s3.stress, e3);
    EXPECT_NEAR(j2_elastic_energy_density<3>(s3.stress, c), w3, 1e-12 * w3);
    // Plane stress: the strain includes the thickness strain the law sets.
    Sym<2> e2;
    e2 << e3[0], e3[1], 0.0, e3[5];
    const J2State<2> s2 = j2_update<2>(zero_state<2>(), e2, c, Kinematics::plane_stress);
    const double w2 = 0.5 * contract<2>(s2.stress, e2);
    EXPECT_NEAR(j2_elastic_energy_density<2>(s2.stress, c), w2, 1e-12 * w2);
  }
}

// Uniaxial stress with step ends on the kinks of the curve: the trapezoidal work Σ ½(σ_n +
// σ_{n+1}) : Δε is then the exact work, and equals stored energy plus plastic work (P21).
TEST(J2ReturnMapping, EnergyBalanceUniaxial) {
  for (const J2Constants& c : {kSteel, kPerfect}) {
    const std::vector<Uniaxial> ends = uniaxial_path(c);
    // The yield strain and the peak strains (where reloading and reverse loading yield).
    const double ey = c.yield_stress / c.young;
    const double reverse_yield = ends[3].eps - 2.0 * ends[3].sigma / c.young;
    std::vector<double> targets;
    const auto add = [&](double from, double to, int n) {
      for (int k = 1; k <= n; ++k) targets.push_back(from + (to - from) * k / n);
    };
    add(0.0, ey, 3);
    add(ey, ends[1].eps, 40);
    add(ends[1].eps, ends[2].eps, 5);
    add(ends[2].eps, ends[1].eps, 5);
    add(ends[1].eps, ends[3].eps, 30);
    add(ends[3].eps, reverse_yield, 7);
    add(reverse_yield, ends[4].eps, 30);

    J2State<3> s = zero_state<3>();
    double eps = 0.0, work = 0.0, plastic_work = 0.0;
    for (double t : targets) {
      const J2State<3> old = s;
      double lateral = 0.0;
      s = uniaxial_step<3>(old, t - eps, c, Kinematics::solid, &lateral);
      Sym<3> de;
      de << t - eps, lateral, lateral, 0.0, 0.0, 0.0;
      eps = t;
      work += 0.5 * contract<3>(old.stress + s.stress, de);
      plastic_work += j2_plastic_work(c, old.plastic_strain, s.plastic_strain);
    }
    const double stored = j2_elastic_energy_density<3>(s.stress, c);
    EXPECT_GT(plastic_work, 10.0 * stored);
    EXPECT_NEAR(stored + plastic_work, work, 1e-10 * work);
    // Closed form of the plastic work: σ_y0 ε̄p + ½ H ε̄p².
    const double ep = s.plastic_strain;
    EXPECT_NEAR(plastic_work, c.yield_stress * ep + 0.5 * c.hardening * ep * ep,
                1e-12 * plastic_work);
  }
}

// --- Constants and supported kinematics -----------------------------------------------------

TEST(J2ReturnMapping, ModuliAndSupportedKinematics) {
  const J2Constants& c = kSteel;
  const double G = c.shear(), K = c.bulk(), l = c.lambda();
  EXPECT_NEAR(K, l + 2.0 * G / 3.0, 1e-12 * K);
  EXPECT_NEAR(9.0 * K * G / (3.0 * K + G), c.young, 1e-12 * c.young);
  EXPECT_NEAR((3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G)), c.poisson, 1e-14);
  EXPECT_TRUE(j2_supports<3>(Kinematics::solid));
  EXPECT_FALSE(j2_supports<3>(Kinematics::plane_stress));
  EXPECT_TRUE(j2_supports<2>(Kinematics::plane_strain));
  EXPECT_TRUE(j2_supports<2>(Kinematics::plane_stress));
  EXPECT_TRUE(j2_supports<2>(Kinematics::axisymmetric));
  EXPECT_FALSE(j2_supports<2>(Kinematics::solid));
}

}  // namespace
}  // namespace pellicle
