// The J2 plasticity material (model "j2-plasticity") at one point, through Material::update:
// uniaxial stress in 3D and plane stress through loading, yield, hardening, elastic unloading
// and reloading against the closed form (P18) of docs/theory/plasticity.md; its columns, the
// Jaumann rotation, energy and wave speed; and the factory's checks of its keys.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "pellicle/core/error.hpp"
#include "pellicle/io/toml_parameters.hpp"
#include "pellicle/mpm/materials/j2_plasticity.hpp"
#include "support/case_text.hpp"

namespace pellicle {
namespace {

constexpr double E = 2.0e5, nu = 0.3, yield = 250.0, H = 2000.0;
constexpr double eps_y = yield / E;  // uniaxial yield strain

J2Constants constants(double hardening = H) {
  return {E, nu, yield, hardening};
}

template <int D>
Particles<D> one_point(J2Plasticity<D>& m, double density = 1.0) {
  Particles<D> p;
  m.declare_columns(p);
  p.bodies.push_back({"b", 0, Vec<D>::Zero(), 0, 0, nullptr});
  p.add(Vec<D>::Zero(), Vec<D>::Zero(), 1.0, density);
  return p;
}

// One update with a constant velocity gradient L over dt.
template <int D>
void step(const J2Plasticity<D>& m, Particles<D>& p, const Mat<D>& L, double dt) {
  const std::vector<Mat<D>> gradient{L};
  const std::vector<double> hoop_rate{0.0};
  m.update(MaterialStep<D>{p, gradient, hoop_rate, dt, 0, 1});
}

// Uniaxial stress σ_xx = σ after an axial strain history with largest value eps_max, without
// reverse yield (P18): ε̄p = max(0, (E ε_max − σ_y0)/(E + H)), σ = E (ε − ε̄p), lateral
// strains −ν σ/E − ε̄p/2. With H = 0 the plateau is σ_y0.
struct Uniaxial {
  double stress, plastic_strain, lateral;
};
Uniaxial exact_uniaxial(double eps, double eps_max, double hardening) {
  const double ep = std::max(0.0, (E * eps_max - yield) / (E + hardening));
  const double s = E * (eps - ep);
  return {s, ep, -nu * s / E - ep / 2.0};
}

// Drives one point in uniaxial stress along the axial strains `path` (one step between
// consecutive entries), prescribing the lateral strain increments of the closed form, and
// checks every step end against it. In plane stress only Δε_yy is prescribed: the return
// finds the thickness strain, which must equal the lateral one (isotropy).
template <int D>
void check_uniaxial_path(Kinematics kinematics, const std::vector<double>& path, double hardening,
                         const std::string& label) {
  J2Plasticity<D> m(kinematics, 1.0, constants(hardening));
  Particles<D> p = one_point<D>(m);
  const auto& eps_p = p.template named<double>("plastic_strain");
  const auto& strain = p.template named<Sym<D>>("strain");
  double eps_max = 0.0;
  Uniaxial before = exact_uniaxial(0.0, 0.0, hardening);
  double largest_plastic = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    eps_max = std::max(eps_max, path[k]);
    const Uniaxial after = exact_uniaxial(path[k], eps_max, hardening);
    Mat<D> L = Mat<D>::Zero();
    L(0, 0) = path[k] - path[k - 1];
    L(1, 1) = after.lateral - before.lateral;
    if constexpr (D == 3) L(2, 2) = after.lateral - before.lateral;
    step<D>(m, p, L, 1.0);
    before = after;
    largest_plastic = std::max(largest_plastic, after.plastic_strain);

    // Radial return is exact for proportional paths at any step size, so only round-off
    // separates the update from (P18): 1e-8 of the stress scale and of the plastic strain
    // scale, as in the return-mapping tests (measured ≤ 6e-15).
    const std::string at =
        label + ", step " + std::to_string(k) + ", eps/eps_y " + std::to_string(path[k] / eps_y);
    const double stress_scale = std::max(std::abs(after.stress), yield);
    const Sym<D>& s = p.stress[0];
    EXPECT_NEAR(s[0], after.stress, 1e-8 * stress_scale) << at;
    for (int c = 1; c < Sym<D>::RowsAtCompileTime; ++c)
      EXPECT_NEAR(s[c], 0.0, 1e-8 * stress_scale) << at << ", component " << c;
    if (kinematics == Kinematics::plane_stress) {
      EXPECT_EQ(s[2], 0.0) << at;
    }
    EXPECT_NEAR(eps_p[0], after.plastic_strain, 1e-8 * std::max(after.plastic_strain, eps_y)) << at;
    // The total strain column: axial and lateral as prescribed; in plane stress the
    // thickness strain the return computed (P15) equals the lateral one (measured ≤ 6e-15
    // of ε_y, bound 1e-8 ε_y).
    EXPECT_NEAR(strain[0][0], path[k], 1e-12 * eps_y) << at;
    EXPECT_NEAR(strain[0][1], after.lateral, 1e-12 * eps_y) << at;
    EXPECT_NEAR(strain[0][2], after.lateral, 1e-8 * eps_y) << at;
  }
  EXPECT_GT(largest_plastic, 4.0 * eps_y) << label;  // the path went well into the plastic range
}

// Load to 8 ε_y, unload elastically to σ = 0, reload to 14 ε_y (past the previous peak, into
// further hardening), in `per_segment` steps per segment, plus a copy whose steps do not
// land on the kinks (each one straddles yield or the reload peak).
std::vector<double> load_unload_reload(int per_segment, double hardening) {
  const double peak = 8.0 * eps_y;
  const double unloaded = exact_uniaxial(0.0, peak, hardening).plastic_strain;  // σ = 0
  const double segments[4] = {0.0, peak, unloaded, 14.0 * eps_y};
  std::vector<double> path{0.0};
  for (int s = 0; s < 3; ++s)
    for (int i = 1; i <= per_segment; ++i)
      path.push_back(segments[s] + (segments[s + 1] - segments[s]) * i / per_segment);
  return path;
}

// Steps across the yield point, a partial unload (no reverse yield: it would start near
// 5.9 ε_y), an elastic reload step, and a step across the previous peak.
const std::vector<double> kStraddling = {0.0,          0.7 * eps_y, 1.9 * eps_y,  8.0 * eps_y,
                                         6.95 * eps_y, 7.5 * eps_y, 11.0 * eps_y, 14.0 * eps_y};

TEST(J2Plasticity, UniaxialStress3DLoadUnloadReload) {
  for (double h : {H, 0.0}) {
    const std::string label = std::string("3D, H = ") + (h > 0 ? "2000" : "0");
    check_uniaxial_path<3>(Kinematics::solid, load_unload_reload(40, h), h, label);
    check_uniaxial_path<3>(Kinematics::solid, load_unload_reload(1, h), h, label + " one step");
    check_uniaxial_path<3>(Kinematics::solid, kStraddling, h, label + " straddling");
  }
}

TEST(J2Plasticity, UniaxialStressPlaneStressLoadUnloadReload) {
  for (double h : {H, 0.0}) {
    const std::string label = std::string("plane stress, H = ") + (h > 0 ? "2000" : "0");
    check_uniaxial_path<2>(Kinematics::plane_stress, load_unload_reload(40, h), h, label);
    check_uniaxial_path<2>(Kinematics::plane_stress, load_unload_reload(1, h), h,
                           label + " one step");
    check_uniaxial_path<2>(Kinematics::plane_stress, kStraddling, h, label + " straddling");
  }
}

// Reloading after unloading is elastic (slope E, ε̄p frozen) up to the previous peak stress
// σ_y0 + H ε̄p, and hardens beyond it with slope E_t = E H/(E + H).
TEST(J2Plasticity, ReloadingYieldsAtThePreviousPeak) {
  J2Plasticity<3> m(Kinematics::solid, 1.0, constants());
  Particles<3> p = one_point<3>(m);
  const auto& eps_p = p.named<double>("plastic_strain");
  std::vector<double> path = load_unload_reload(40, H);
  const double peak_strain = 8.0 * eps_y;
  double eps_max = 0.0;
  Uniaxial before{0.0, 0.0, 0.0};
  for (std::size_t k = 1; k < path.size(); ++k) {
    eps_max = std::max(eps_max, path[k]);
    const Uniaxial after = exact_uniaxial(path[k], eps_max, H);
    Mat3 L = Mat3::Zero();
    L(0, 0) = path[k] - path[k - 1];
    L(1, 1) = L(2, 2) = after.lateral - before.lateral;
    const double stress_before = p.stress[0][0], ep_before = eps_p[0];
    step<3>(m, p, L, 1.0);
    before = after;
    const double slope = (p.stress[0][0] - stress_before) / L(0, 0);
    const bool reloading = k > 80;
    if (reloading && path[k] <= peak_strain) {
      EXPECT_NEAR(slope, E, 1e-8 * E) << "step " << k;
      EXPECT_EQ(eps_p[0], ep_before) << "step " << k;
    }
    if (reloading && path[k - 1] >= peak_strain) {
      EXPECT_NEAR(slope, E * H / (E + H), 1e-8 * E) << "step " << k;
      EXPECT_NEAR(p.stress[0][0], yield + H * eps_p[0], 1e-10 * yield) << "step " << k;
    }
  }
}

TEST(J2Plasticity, DeclaresPlasticStrainForSnapshotsAndCheckpoints) {
  J2Plasticity<2> m(Kinematics::plane_strain, 1.0, constants());
  Particles<2> p;
  m.declare_columns(p);
  J2Plasticity<2> other(Kinematics::plane_strain, 2.0, constants(0.0));
  other.declare_columns(p);  // a second J2 material shares the columns
  ASSERT_EQ(p.columns.count(), 2);
  const Column<double> c = p.columns.find<double>("plastic_strain");
  ASSERT_TRUE(c.valid());
  EXPECT_EQ(p.columns.spec(c.index).unit, "1");
  EXPECT_TRUE(p.columns.spec(c.index).snapshot);
  EXPECT_TRUE(p.columns.spec(c.index).checkpoint);
  EXPECT_EQ(p.columns.shape(c.index), ColumnShape::scalar);
  EXPECT_TRUE(p.columns.find<Sym<2>>("strain").valid());
}

// A rigid spin of a yielded point rotates its stress (Jaumann rate, (P2)) and keeps it on the
// yield surface. The explicit rotation σ + Δt (Wσ − σW) grows |s| by O((ωΔt)²) per step, and
// the return turns that into plastic strain: ε̄p may creep by about N (ωΔt)² q / (3G + H).
TEST(J2Plasticity, SpinRotatesAYieldedStress) {
  J2Plasticity<2> m(Kinematics::plane_strain, 1.0, constants());
  Particles<2> p = one_point<2>(m);
  const auto& eps_p = p.named<double>("plastic_strain");
  Mat<2> stretch = Mat<2>::Zero();
  stretch(0, 0) = 5.0 * eps_y;  // uniaxial strain, well past yield in one step
  step<2>(m, p, stretch, 1.0);
  ASSERT_GT(eps_p[0], 0.0);
  const Mat3 s0 = to_mat3<2>(p.stress[0]);
  const double ep0 = eps_p[0], q0 = von_mises_stress<2>(p.stress[0]);
  const double omega = 1.0, angle = 0.5;
  const int steps = 20000;
  const double dt = angle / (omega * steps);
  Mat<2> L = Mat<2>::Zero();
  L(0, 1) = -omega;
  L(1, 0) = omega;
  for (int i = 0; i < steps; ++i) step<2>(m, p, L, dt);
  Mat3 R = Mat3::Identity();
  R(0, 0) = R(1, 1) = std::cos(angle);
  R(1, 0) = std::sin(angle);
  R(0, 1) = -std::sin(angle);
  const Mat3 expected = R * s0 * R.transpose();
  // The first-order rotation drifts by ~N (ωΔt)² = 1.25e-5 of |σ|; 1e-4 of |σ| bounds it.
  EXPECT_LT((to_mat3<2>(p.stress[0]) - expected).norm(), 1e-4 * s0.norm());
  EXPECT_NEAR(von_mises_stress<2>(p.stress[0]), yield + H * eps_p[0], 1e-10 * yield);
  const double G = E / (2 * (1 + nu));
  const double creep = steps * (omega * dt) * (omega * dt) * q0 / (3 * G + H);
  EXPECT_GE(eps_p[0], ep0);
  EXPECT_LT(eps_p[0] - ep0, 4.0 * creep);  // measured 1.5 × the estimate
}

TEST(J2Plasticity, StoredEnergyIsElasticOnly) {
  // Uniaxial stress to 6 ε_y: stored energy σ²/(2E) V, not the work σ_y0 ε̄p + … done.
  J2Plasticity<3> m(Kinematics::solid, 2.0, constants());
  Particles<3> p = one_point<3>(m, 2.0);
  p.volume[0] = 0.25;
  const Uniaxial u = exact_uniaxial(6.0 * eps_y, 6.0 * eps_y, H);
  Mat3 L = Mat3::Zero();
  L(0, 0) = 6.0 * eps_y;
  L(1, 1) = L(2, 2) = u.lateral;
  step<3>(m, p, L, 1.0);
  ASSERT_NEAR(p.stress[0][0], u.stress, 1e-8 * u.stress);
  const double s = p.stress[0][0];
  EXPECT_NEAR(m.strain_energy(p, 0, 1), 0.25 * s * s / (2.0 * E), 1e-10 * 0.25 * s * s / E);

  // Plane-strain uniaxial strain ε to 5 ε_y: the stress is triaxial and σ_zz ≠ 0. The elastic
  // strain is the total minus ε̄p (1, −½, −½), and the stored energy ½ σ : ε_e V.
  J2Plasticity<2> ps(Kinematics::plane_strain, 1.0, constants());
  Particles<2> q = one_point<2>(ps);
  q.volume[0] = 0.25;
  const double e = 5.0 * eps_y;
  Mat<2> stretch = Mat<2>::Zero();
  stretch(0, 0) = e;
  step<2>(ps, q, stretch, 1.0);
  const double ep = q.named<double>("plastic_strain")[0];
  ASSERT_GT(ep, 0.0);
  const Sym<2>& t = q.stress[0];
  const double half_stress_strain = 0.5 * (t[0] * (e - ep) + (t[1] + t[2]) * 0.5 * ep);
  EXPECT_NEAR(ps.strain_energy(q, 0, 1), 0.25 * half_stress_strain,
              1e-10 * 0.25 * half_stress_strain);
}

TEST(J2Plasticity, WaveSpeedIsElastic) {
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  J2Plasticity<2> strain(Kinematics::plane_strain, 4.0, constants());
  J2Plasticity<2> stress(Kinematics::plane_stress, 4.0, constants());
  J2Plasticity<3> solid(Kinematics::solid, 4.0, constants());
  Particles<2> p = one_point<2>(strain, 4.0);
  Particles<3> p3 = one_point<3>(solid, 4.0);
  EXPECT_NEAR(strain.max_signal_speed(p, 0, 1, 0.1), std::sqrt((lambda + 2 * mu) / 4.0), 1e-12);
  EXPECT_NEAR(stress.max_signal_speed(p, 0, 1, 0.1), std::sqrt(E / ((1 - nu * nu) * 4.0)), 1e-12);
  EXPECT_NEAR(solid.max_signal_speed(p3, 0, 1, 0.1), std::sqrt((lambda + 2 * mu) / 4.0), 1e-12);
  p.density[0] = 1.0;  // a point that expanded: the fastest wave is where ρ is smallest
  EXPECT_NEAR(strain.max_signal_speed(p, 0, 1, 0.1), std::sqrt(lambda + 2 * mu), 1e-12);
}

TEST(J2Plasticity, InitialStrainIsElastic) {
  J2Plasticity<2> m(Kinematics::plane_stress, 1.0, constants());
  Sym<2> e;
  e << 1e-4, -0.3e-4, 0.0, 2e-4;
  const Sym<2> s = m.stress_from_strain(e);
  const double c = E / (1 - nu * nu), mu = E / (2 * (1 + nu));
  EXPECT_NEAR(s[0], c * (e[0] + nu * e[1]), 1e-12 * E * 1e-4);
  EXPECT_NEAR(s[1], c * (nu * e[0] + e[1]), 1e-12 * E * 1e-4);
  EXPECT_EQ(s[2], 0.0);
  EXPECT_NEAR(s[3], 2 * mu * e[3], 1e-12 * E * 1e-4);
  J2Plasticity<3> solid(Kinematics::solid, 1.0, constants());
  Sym<3> e3;
  e3 << 1e-4, 0.0, 0.0, 0.0, 0.0, 0.0;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  EXPECT_NEAR(solid.stress_from_strain(e3)[0], (lambda + 2 * mu) * 1e-4, 1e-12 * E * 1e-4);
  EXPECT_NEAR(solid.stress_from_strain(e3)[1], lambda * 1e-4, 1e-12 * E * 1e-4);
}

// --- The factory and the case reader ---------------------------------------------------------

const std::string kCase = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.1

[solver]
end_time = 0.1

[[material]]
name = "steel"
model = "j2-plasticity"
density = 7800.0
youngs_modulus = 2e11
poisson_ratio = 0.3
yield_stress = 2.5e8
hardening_modulus = 2e9

[[body]]
name = "block"
material = "steel"
region = { shape = "box", lower = [0.2, 0.2], upper = [0.6, 0.6] }
)";

using testing::problems_of;

TEST(J2Plasticity, CaseKeysAreRead) {
  EXPECT_EQ(problems_of(kCase), "");
  auto s = testing::simulation_from_text<2>(kCase);
  const auto* j2 = dynamic_cast<const J2Plasticity<2>*>(&s->material(0));
  ASSERT_NE(j2, nullptr);
  EXPECT_EQ(j2->density(), 7800.0);
  EXPECT_EQ(j2->constants().young, 2e11);
  EXPECT_EQ(j2->constants().poisson, 0.3);
  EXPECT_EQ(j2->constants().yield_stress, 2.5e8);
  EXPECT_EQ(j2->constants().hardening, 2e9);
  EXPECT_EQ(s->points().named<double>("plastic_strain").size(), s->points().position.size());
  // Defaults: ν = 0, H = 0 (perfect plasticity).
  std::string text = kCase;
  for (const std::string key : {"poisson_ratio = 0.3\n", "hardening_modulus = 2e9\n"})
    text.erase(text.find(key), key.size());
  auto d = testing::simulation_from_text<2>(text);
  const auto& defaults = dynamic_cast<const J2Plasticity<2>&>(d->material(0)).constants();
  EXPECT_EQ(defaults.poisson, 0.0);
  EXPECT_EQ(defaults.hardening, 0.0);
}

TEST(J2Plasticity, FactoryRejectsBadKeys) {
  std::string msg = problems_of(kCase, {"material[0].yield_stress=-2.5e8"});
  EXPECT_NE(msg.find("material[0].yield_stress: expected a number > 0, found the number"),
            std::string::npos)
      << msg;
  msg = problems_of(kCase, {"material[0].yield_stress=0.0"});
  EXPECT_NE(msg.find("material[0].yield_stress: expected a number > 0"), std::string::npos) << msg;
  msg = problems_of(kCase, {"material[0].hardening_modulus=-1.0"});
  EXPECT_NE(msg.find("material[0].hardening_modulus: expected a number >= 0"), std::string::npos)
      << msg;
  msg = problems_of(kCase, {"material[0].poisson_ratio=0.5"});
  EXPECT_NE(msg.find("material[0].poisson_ratio: expected a number in (-1, 0.5)"),
            std::string::npos)
      << msg;
  msg = problems_of(kCase, {"material[0].youngs_modulus=0.0"});
  EXPECT_NE(msg.find("material[0].youngs_modulus: expected a number > 0"), std::string::npos)
      << msg;
  std::string text = kCase;
  const std::string line = "yield_stress = 2.5e8\n";
  text.erase(text.find(line), line.size());
  msg = problems_of(text);
  EXPECT_NE(msg.find("material[0].yield_stress: expected a number > 0, found nothing (required)"),
            std::string::npos)
      << msg;
  // A misspelt key is unknown, not silently the default.
  msg = problems_of(kCase, {"material[0].hardening=1.0"});
  EXPECT_NE(msg.find("material[0].hardening: unknown key"), std::string::npos) << msg;
}

// Kinematics the return mapping does not handle (j2_supports) are refused by the factory
// with a problem on the material's `model` key. The case reader never pairs a 2D grid with
// `solid` or a 3D grid with a 2D kinematics, so the factory is called directly here.
template <int D>
std::string factory_problems(Kinematics kinematics) {
  const std::string text =
      "density = 7800.0\nyoungs_modulus = 2e11\npoisson_ratio = 0.3\nyield_stress = 2.5e8\n";
  const toml::table table = toml::parse(std::string_view(text), std::string_view("case.toml"));
  ProblemList problems{"case.toml", {}};
  {
    TomlParameters in(table, "material[0]", problems);
    make_j2_plasticity<D>(in, kinematics);
  }
  std::string messages;
  for (const auto& p : problems.problems) messages += p.format() + "\n";
  return messages;
}

TEST(J2Plasticity, FactoryRefusesUnsupportedKinematics) {
  EXPECT_EQ(factory_problems<2>(Kinematics::plane_strain), "");
  EXPECT_EQ(factory_problems<2>(Kinematics::plane_stress), "");
  EXPECT_EQ(factory_problems<2>(Kinematics::axisymmetric), "");
  EXPECT_EQ(factory_problems<3>(Kinematics::solid), "");
  for (const std::string& msg :
       {factory_problems<2>(Kinematics::solid), factory_problems<3>(Kinematics::plane_strain),
        factory_problems<3>(Kinematics::plane_stress)}) {
    EXPECT_NE(msg.find("material[0].model: j2-plasticity needs grid.kinematics"), std::string::npos)
        << msg;
  }
}

}  // namespace
}  // namespace pellicle
