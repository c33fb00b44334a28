// The contact rules at one grid node that two bodies share (IJNME 1999 §4.1, thesis A.1.3;
// mpm/contact/). Body "left" (node mass m₁ = 2, one point left of the node, outward normal
// n₁ = +x from its colour function) meets body "right" (m₂ = 1, one point right of the node,
// n₂ = −x). The centre-of-mass velocity is v_cm = (m₁v₁ + m₂v₂)/(m₁ + m₂) (eqs 20–22). The
// laws checked, with numbers worked by hand in each test:
//   - every registered rule: bodies approaching head-on both leave with v_cm, so the node's
//     momentum m₁v₁ + m₂v₂ is kept to round-off and the contact forces m_I Δv_I / Δt balance;
//   - release (York, eqs 9.7–9.9 / IJNME eq 26): approaching bodies move with v_cm (no
//     penetration, no slip); separating ones keep their own velocities and FLIP increments;
//     the test reads the velocities mapped from the points before the forces act (eq 25),
//     and the decision taken on the Lagrangian pass holds for the MUSL convected pass;
//   - friction (Coulomb, Bardenhagen, Brackbill & Sulsky 2000): an approaching body loses
//     its normal velocity relative to v_cm, a, and of its tangential relative velocity t the
//     part min(|t|, μ a) (stick when μ a ≥ |t|, slip otherwise); separating bodies are free.
#include <gtest/gtest.h>

#include <toml++/toml.h>

#include <map>
#include <memory>
#include <string>

#include "pellicle/io/toml_parameters.hpp"
#include "pellicle/mpm/contact/contact_model.hpp"
#include "pellicle/mpm/materials/linear_elastic.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {
namespace {

constexpr double kDt = 0.01;
constexpr double kTolerance = 1e-12;  // the rules are a few products: round-off only
constexpr double kLeftMass = 2.0, kRightMass = 1.0;

//! The contact model `name` of the registry, made from the [contact] table `table`.
std::unique_ptr<ContactModel<2>> make_model(const std::string& name, const std::string& table) {
  const toml::table parsed = toml::parse(std::string_view(table), std::string_view("case.toml"));
  ProblemList problems{"case.toml", {}};
  std::unique_ptr<ContactModel<2>> model;
  {
    TomlParameters in(parsed, "contact", problems);
    for (const auto& choice : contact_models<2>())
      if (choice.name == name) model = choice.make(in, {"left", "right"});
  }
  problems.throw_if_any();
  if (!model) throw std::invalid_argument("no contact model named " + name);
  return model;
}

//! Two one-point bodies on a 4 × 4 grid of unit cells, sharing the node at (2, 2).
//!
//! Their points sit at (1.5, 2) and (2.5, 2). A point's colour spreads to cell centres with
//! the quadratic B-spline S (S(0) = 3/4, S(±1/2) = 1/2, S(±1) = 1/8), so for the left
//! point the four cells around the node hold V S(0) S(½) on its side and V S(1) S(½) on the
//! other: the colour falls off toward +x and is symmetric in y, so its outward normal at the
//! node is exactly +x (eq 28); the right body's is −x.
class TwoBodyNode {
 public:
  explicit TwoBodyNode(std::unique_ptr<ContactModel<2>> model) {
    FaceConditions<2> faces;
    faces.fill(FaceCondition::free);  // no face constrains or mirrors the node
    Grid<2> grid(Vec2::Zero(), Vec2(4.0, 4.0), 1.0, faces);
    Particles<2> points;
    points.bodies.push_back({"left", 0, Vec2::Zero(), 0, 0, nullptr});
    points.add(Vec2(1.5, 2.0), Vec2::Zero(), 1.0, 1000.0);
    points.bodies.push_back({"right", 0, Vec2::Zero(), 1, 1, nullptr});
    points.add(Vec2(2.5, 2.0), Vec2::Zero(), 1.0, 1000.0);
    std::vector<std::unique_ptr<Material<2>>> materials;
    materials.push_back(
        std::make_unique<LinearElastic<2>>(Kinematics::plane_strain, 1000.0, 1.0e6, 0.3));
    std::unique_ptr<Transfer<2>> transfer;
    for (const auto& kernel : kernel_choices<2>())
      if (kernel.name == "linear") transfer = kernel.make(TransferOptions{}, 1.0);
    simulation_ =
        std::make_unique<Simulation<2>>(SimulationSettings{}, std::move(grid), std::move(points),
                                        std::move(materials), std::move(transfer), Vec2::Zero());
    simulation_->set_contact(std::move(model));
    const Grid<2>& g = simulation_->grid();
    for (long n = 0; n < g.node_count(); ++n)
      if ((g.node_position(n) - Vec2(2.0, 2.0)).norm() < 1e-12) node_ = n;
  }

  //! Body b's own field at the node: its new velocity and the change over the step (the
  //! velocity mapped from its points is v − Δv). Sets the centre-of-mass field as their
  //! mass-weighted sum, as to_grid and the momentum update leave it (eqs 20–22).
  void set(const Vec2& left, const Vec2& right, const Vec2& left_change = Vec2::Zero(),
           const Vec2& right_change = Vec2::Zero()) {
    GridFields<2>& fields = simulation_->fields();
    const double m[2] = {kLeftMass, kRightMass};
    const Vec2 v[2] = {left, right}, dv[2] = {left_change, right_change};
    Grid<2>& cm = fields.centre_of_mass();
    cm.mass[node_] = m[0] + m[1];
    cm.velocity[node_] = (m[0] * v[0] + m[1] * v[1]) / (m[0] + m[1]);
    cm.velocity_change[node_] = (m[0] * dv[0] + m[1] * dv[1]) / (m[0] + m[1]);
    for (int b = 0; b < 2; ++b) {
      Grid<2>& g = fields.field(b);
      g.mass[node_] = m[b];
      g.velocity[node_] = v[b];
      g.velocity_change[node_] = dv[b];
    }
  }

  //! The contact hook after a grid update, as Simulation::grid and ::remap call it.
  void resolve(GridPass pass = GridPass::lagrangian) {
    simulation_->hooks().back()->after_grid_update(*simulation_, pass, kDt);
  }

  Vec2 velocity(int body) const { return simulation_->fields().field(body).velocity[node_]; }
  Vec2 change(int body) const { return simulation_->fields().field(body).velocity_change[node_]; }
  Vec2 force(int body) const { return simulation_->contact_forces()->at(body); }
  Vec2 momentum() const { return kLeftMass * velocity(0) + kRightMass * velocity(1); }

 private:
  std::unique_ptr<Simulation<2>> simulation_;
  long node_ = -1;
};

void expect_near(const Vec2& got, const Vec2& expected, const char* what) {
  EXPECT_NEAR(got.x(), expected.x(), kTolerance) << what;
  EXPECT_NEAR(got.y(), expected.y(), kTolerance) << what;
}

//! Parameters each registered model needs here; a model registered without an entry fails
//! the first test, so that it is added to these checks.
const std::map<std::string, std::string>& parameters_of_each_model() {
  static const std::map<std::string, std::string> tables = {
      {"release", ""},
      {"friction", "coefficient = 0.3\n"},
  };
  return tables;
}

// Head-on, v₁ = (1, 0), v₂ = (−1, 0): v_cm = (2·1 − 1·1)/3 = 1/3 along x. Every rule stops
// the approach: both bodies leave with (1/3, 0); momentum (1, 0) is kept; the contact forces
// are m₁(1/3 − 1)/Δt = −(4/3)/Δt on the left body and +(4/3)/Δt on the right one.
TEST(ContactRules, EveryRegisteredRuleStopsAHeadOnApproachKeepingMomentum) {
  ASSERT_FALSE(contact_models<2>().empty());
  for (const auto& choice : contact_models<2>()) {
    SCOPED_TRACE(choice.name);
    const auto parameters = parameters_of_each_model().find(choice.name);
    ASSERT_NE(parameters, parameters_of_each_model().end())
        << "contact model '" << choice.name << "' is registered but not tested here";
    TwoBodyNode node(make_model(choice.name, parameters->second));
    node.set(Vec2(1.0, 0.0), Vec2(-1.0, 0.0));
    node.resolve();
    expect_near(node.velocity(0), Vec2(1.0 / 3.0, 0.0), "left velocity");
    expect_near(node.velocity(1), Vec2(1.0 / 3.0, 0.0), "right velocity");
    expect_near(node.momentum(), Vec2(1.0, 0.0), "momentum at the node");
    expect_near(node.force(0) * kDt, Vec2(-4.0 / 3.0, 0.0), "contact impulse on the left body");
    expect_near(node.force(1) * kDt, Vec2(4.0 / 3.0, 0.0), "contact impulse on the right body");
  }
}

// v₁ = (1, 0.3), v₂ = (−1, −0.6): v_cm = ((2 − 1)/3, (0.6 − 0.6)/3) = (1/3, 0). Contact
// in York's rule is the centre-of-mass field: no penetration and no slip, so both bodies
// take (1/3, 0), and their FLIP increments are the centre-of-mass field's (eqs 20–22).
TEST(ContactRules, ReleaseRuleMovesApproachingBodiesTogetherWithoutSlip) {
  for (const char* criterion : {"body-body", "body-centre-of-mass", "both"}) {
    SCOPED_TRACE(criterion);
    TwoBodyNode node(make_model("release", std::string("criterion = \"") + criterion + "\"\n"));
    // Increments chosen so that the mapped velocities v − Δv still approach: (0.5, 0.3) and
    // (−0.5, −0.6); the centre-of-mass increment is (2·0.5 − 0.5)/3 = 1/6 along x.
    node.set(Vec2(1.0, 0.3), Vec2(-1.0, -0.6), Vec2(0.5, 0.0), Vec2(-0.5, 0.0));
    node.resolve();
    expect_near(node.velocity(0), Vec2(1.0 / 3.0, 0.0), "left velocity");
    expect_near(node.velocity(1), Vec2(1.0 / 3.0, 0.0), "right velocity");
    expect_near(node.change(0), Vec2(1.0 / 6.0, 0.0), "left FLIP increment");
    expect_near(node.change(1), Vec2(1.0 / 6.0, 0.0), "right FLIP increment");
    expect_near(node.momentum(), Vec2(1.0, 0.0), "momentum at the node");
    expect_near(node.force(0) + node.force(1), Vec2::Zero(), "sum of the contact forces");
  }
}

// v₁ = (−1, 0.3), v₂ = (1, −0.6): (v₁ − v_cm)·n₁ = (−1 − (−1/3))·1 < 0 and
// (v₂ − v_cm)·n₂ = −(1 + 1/3) < 0: every criterion releases, and each body keeps its own
// velocity and FLIP increment; no contact force acts.
TEST(ContactRules, ReleaseRuleLeavesSeparatingBodiesAlone) {
  for (const char* criterion : {"body-body", "body-centre-of-mass", "both"}) {
    SCOPED_TRACE(criterion);
    TwoBodyNode node(make_model("release", std::string("criterion = \"") + criterion + "\"\n"));
    node.set(Vec2(-1.0, 0.3), Vec2(1.0, -0.6), Vec2(0.25, 0.5), Vec2(-0.25, 0.125));
    node.resolve();
    EXPECT_EQ(node.velocity(0), Vec2(-1.0, 0.3));
    EXPECT_EQ(node.velocity(1), Vec2(1.0, -0.6));
    EXPECT_EQ(node.change(0), Vec2(0.25, 0.5));
    EXPECT_EQ(node.change(1), Vec2(-0.25, 0.125));
    EXPECT_EQ(node.force(0), Vec2::Zero());
    EXPECT_EQ(node.force(1), Vec2::Zero());
  }
}

// The criterion reads the velocities mapped from the points before the forces act (IJNME
// eq 25), not the updated ones. New velocities v₁ = (−1, 0), v₂ = (1, 0) separate, but
// with increments Δv₁ = (−2, 0), Δv₂ = (2, 0) the mapped ones, (1, 0) and (−1, 0),
// approach: contact, so both take v_cm = (2·(−1) + 1)/3 = −1/3 along x. Swapping the
// increments' signs gives separating mapped velocities (−3, 0), (3, 0) behind approaching
// new ones: release, velocities untouched.
TEST(ContactRules, ReleaseDecidesOnTheVelocitiesMappedFromThePoints) {
  for (const char* criterion : {"body-body", "body-centre-of-mass", "both"}) {
    SCOPED_TRACE(criterion);
    const std::string table = std::string("criterion = \"") + criterion + "\"\n";
    {
      TwoBodyNode node(make_model("release", table));
      node.set(Vec2(-1.0, 0.0), Vec2(1.0, 0.0), Vec2(-2.0, 0.0), Vec2(2.0, 0.0));
      node.resolve();
      expect_near(node.velocity(0), Vec2(-1.0 / 3.0, 0.0), "left velocity");
      expect_near(node.velocity(1), Vec2(-1.0 / 3.0, 0.0), "right velocity");
    }
    {
      TwoBodyNode node(make_model("release", table));
      node.set(Vec2(1.0, 0.0), Vec2(-1.0, 0.0), Vec2(4.0, 0.0), Vec2(-4.0, 0.0));
      node.resolve();
      EXPECT_EQ(node.velocity(0), Vec2(1.0, 0.0));
      EXPECT_EQ(node.velocity(1), Vec2(-1.0, 0.0));
    }
  }
}

// The MUSL remap's convected velocities follow the Lagrangian pass's decision: bodies in
// contact there share v_cm on the convected pass even where their convected velocities
// separate (v_cm = (2·(−1) + 1)/3 = −1/3); released bodies keep approaching convected
// velocities (1, 0) and (−1, 0).
TEST(ContactRules, ReleaseKeepsTheLagrangianDecisionForTheConvectedPass) {
  {
    TwoBodyNode node(make_model("release", ""));
    node.set(Vec2(1.0, 0.0), Vec2(-1.0, 0.0));
    node.resolve(GridPass::lagrangian);
    node.set(Vec2(-1.0, 0.0), Vec2(1.0, 0.0));
    node.resolve(GridPass::convected);
    expect_near(node.velocity(0), Vec2(-1.0 / 3.0, 0.0), "left convected velocity");
    expect_near(node.velocity(1), Vec2(-1.0 / 3.0, 0.0), "right convected velocity");
  }
  {
    TwoBodyNode node(make_model("release", ""));
    node.set(Vec2(-1.0, 0.0), Vec2(1.0, 0.0));
    node.resolve(GridPass::lagrangian);
    node.set(Vec2(1.0, 0.0), Vec2(-1.0, 0.0));
    node.resolve(GridPass::convected);
    EXPECT_EQ(node.velocity(0), Vec2(1.0, 0.0));
    EXPECT_EQ(node.velocity(1), Vec2(-1.0, 0.0));
  }
}

// v₁ = (1, 0.3), v₂ = (−1, −0.6), v_cm = (1/3, 0). Relative to v_cm the left body has
// normal approach a₁ = 2/3 and tangential slip t₁ = (0, 0.3); the right one a₂ = 4/3 and
// t₂ = (0, −0.6). Both lose their normal approach; the x velocities become 1/3.
//   μ = 0.5: μa₁ = 1/3 ≥ 0.3, μa₂ = 2/3 ≥ 0.6: both stick, v₁ = v₂ = (1/3, 0).
//   μ = 0.3: μa₁ = 0.2 < 0.3, μa₂ = 0.4 < 0.6: both slip, v₁ = (1/3, 0.3 − 0.2),
//            v₂ = (1/3, −0.6 + 0.4). The tangential impulse on the left body,
//            m₁·0.2 = 0.4, is μ times its normal impulse m₁·(2/3) = 4/3.
//   μ = 0:   frictionless: tangential velocities untouched, (1/3, 0.3) and (1/3, −0.6).
//   μ = inf: no slip, as μ = 0.5.
// In every case the node's momentum (1, 0) is kept.
TEST(ContactRules, FrictionSticksBelowTheCoulombBoundAndSlipsAtIt) {
  struct Case {
    const char* coefficient;
    Vec2 left, right;
  };
  const Case cases[] = {
      {"0.5", Vec2(1.0 / 3.0, 0.0), Vec2(1.0 / 3.0, 0.0)},
      {"0.3", Vec2(1.0 / 3.0, 0.1), Vec2(1.0 / 3.0, -0.2)},
      {"0.0", Vec2(1.0 / 3.0, 0.3), Vec2(1.0 / 3.0, -0.6)},
      {"inf", Vec2(1.0 / 3.0, 0.0), Vec2(1.0 / 3.0, 0.0)},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string("mu = ") + c.coefficient);
    TwoBodyNode node(make_model("friction", std::string("coefficient = ") + c.coefficient + "\n"));
    node.set(Vec2(1.0, 0.3), Vec2(-1.0, -0.6), Vec2(0.5, 0.25), Vec2(-0.5, 0.0));
    node.resolve();
    expect_near(node.velocity(0), c.left, "left velocity");
    expect_near(node.velocity(1), c.right, "right velocity");
    expect_near(node.momentum(), Vec2(1.0, 0.0), "momentum at the node");
    // Outside contact a body's FLIP increment takes the rule's correction on top of its own.
    expect_near(node.change(0), Vec2(0.5, 0.25) + c.left - Vec2(1.0, 0.3), "left FLIP increment");
    expect_near(node.change(1), Vec2(-0.5, 0.0) + c.right - Vec2(-1.0, -0.6),
                "right FLIP increment");
    expect_near(node.force(0) + node.force(1), Vec2::Zero(), "sum of the contact forces");
    expect_near(node.force(0) * kDt, kLeftMass * (c.left - Vec2(1.0, 0.3)),
                "contact impulse on the left body");
  }
}

// Separating (v₁ = (−1, 0.3), v₂ = (1, −0.6), both moving away from v_cm along their
// normals): friction leaves both velocities as they are, however large μ.
TEST(ContactRules, FrictionLetsSeparatingBodiesGo) {
  for (const char* coefficient : {"0.3", "inf"}) {
    SCOPED_TRACE(coefficient);
    TwoBodyNode node(make_model("friction", std::string("coefficient = ") + coefficient + "\n"));
    node.set(Vec2(-1.0, 0.3), Vec2(1.0, -0.6));
    node.resolve();
    EXPECT_EQ(node.velocity(0), Vec2(-1.0, 0.3));
    EXPECT_EQ(node.velocity(1), Vec2(1.0, -0.6));
    EXPECT_EQ(node.force(0), Vec2::Zero());
    EXPECT_EQ(node.force(1), Vec2::Zero());
  }
}

}  // namespace
}  // namespace pellicle
