// York's contact-release algorithm (IJNME §4.1 eq 26; thesis A.1.3 eqs 9.7–9.9). At a node
// that bodies share, either all of them move in the centre-of-mass field (contact: no
// penetration, no slip) or each in its own field (release). The criteria, with n^I the
// outward normal of body I and v the nodal velocities mapped from the points (before the
// forces act, IJNME eqs 22 and 25); the relations were lost from both texts and follow
// from their meaning (docs/theory/contact.md):
//   body-body (9.7)            release if (v^m − v^J) · n^m < 0 for the other bodies J
//   body-centre-of-mass (9.8)  release if (v^m − v^cm) · n^m < 0
//   both (9.9, IJNME eq 26)    release if (v^I − v^cm) · n^I < 0 for every body I there
// m is the master body where it shares the node, else the first body there. With
// criterion 9.9 a node keeps its state (contact or release) from the step before unless
// every body's test agrees on the change (thesis A.1.3); `hysteresis = false` re-decides
// every step from the tests alone.
#include <algorithm>
#include <string>
#include <vector>

#include "pellicle/mpm/contact/contact_model.hpp"

namespace pellicle {
namespace {

enum class ReleaseCriterion { body_body, body_centre_of_mass, both };

template <int D>
class Release final : public ContactModel<D> {
 public:
  Release(ReleaseCriterion criterion, int master, std::string master_name, bool hysteresis)
      : criterion_(criterion),
        master_(master),
        master_name_(std::move(master_name)),
        hysteresis_(hysteresis) {}

  std::string describe() const override {
    const char* names[] = {"body-body (eq 9.7)", "body-centre-of-mass (eq 9.8)", "both (eq 9.9)"};
    return std::string("release, criterion ") + names[static_cast<int>(criterion_)] + ", master '" +
           master_name_ + "'" + (hysteresis_ ? ", state kept unless all bodies agree" : "");
  }

  void resolve(GridFields<D>& fields, const Particles<D>& points, double dt,
               GridPass pass) override {
    // The decision is taken once per step, on the Lagrangian pass, and kept for the
    // convected velocities, so bodies that moved together also deform together.
    const long nodes = fields.centre_of_mass().node_count();
    if (pass == GridPass::lagrangian) {
      previous_.swap(released_);
      previous_.resize(nodes, kNotShared);
      released_.assign(nodes, kNotShared);
    }
    this->shared_.sweep(fields, points, dt, pass, [this, pass](SharedNode<D>& node) {
      if (pass == GridPass::lagrangian) released_[node.index] = decide(node);
      if (released_[node.index] != kReleased)
        for (int k = 0; k < node.count; ++k) node.in_contact[k] = true;
    });
  }

  //! Criterion 9.9 keeps each node's last state: a restart needs it to continue the same way.
  std::string state_name() const override { return "contact-release"; }
  HookState save_state() const override {
    return {{"node_state", std::vector<double>(released_.begin(), released_.end()), true}};
  }
  void load_state(const HookState& state) override {
    for (const auto& array : state)
      if (array.name == "node_state") released_.assign(array.values.begin(), array.values.end());
  }
  void grid_replaced(const NodeCarrier& carrier) override {
    std::vector<double> state(released_.begin(), released_.end());
    carrier.carry(state);
    released_.assign(state.begin(), state.end());
  }

 private:
  static constexpr char kNotShared = 0, kContact = 1, kReleased = 2;

  char decide(const SharedNode<D>& node) const {
    if (!hysteresis_ || criterion_ != ReleaseCriterion::both)
      return releases(node) ? kReleased : kContact;
    // Thesis A.1.3 on eq 9.9: "Release is allowed only if both criteria agree, and
    // subsequent changes to contact, release, etc. are allowed only then": a node changes
    // state only when every body's test agrees; otherwise it keeps last step's state
    // (contact where it was not shared before).
    bool all_release = true, all_contact = true;
    for (int k = 0; k < node.count; ++k) {
      if (node.normal[k].isZero()) return kContact;
      const bool separating =
          (node.mapped[k] - node.centre_of_mass_mapped).dot(node.normal[k]) < 0.0;
      all_release = all_release && separating;
      all_contact = all_contact && !separating;
    }
    if (all_release) return kReleased;
    if (all_contact) return kContact;
    const char before = previous_[node.index];
    return before == kNotShared ? kContact : before;
  }

  bool releases(const SharedNode<D>& node) const {
    int m = 0;
    for (int k = 0; k < node.count; ++k)
      if (node.body[k] == master_) m = k;
    // Without a normal there is no way to tell separation: keep the bodies together.
    for (int k = 0; k < node.count; ++k)
      if (node.normal[k].isZero()) return false;
    switch (criterion_) {
      case ReleaseCriterion::body_body:
        for (int k = 0; k < node.count; ++k)
          if (k != m && (node.mapped[m] - node.mapped[k]).dot(node.normal[m]) >= 0.0) return false;
        return true;
      case ReleaseCriterion::body_centre_of_mass:
        return (node.mapped[m] - node.centre_of_mass_mapped).dot(node.normal[m]) < 0.0;
      case ReleaseCriterion::both:
        for (int k = 0; k < node.count; ++k)
          if ((node.mapped[k] - node.centre_of_mass_mapped).dot(node.normal[k]) >= 0.0)
            return false;
        return true;
    }
    return false;
  }

  ReleaseCriterion criterion_;
  int master_;
  std::string master_name_;
  bool hysteresis_;
  std::vector<char> released_;  //!< per node, this step's state
  std::vector<char> previous_;  //!< per node, last step's state
};

}  // namespace

template <int D>
std::unique_ptr<ContactModel<D>> make_release(ParameterReader& in,
                                              const std::vector<std::string>& body_names) {
  const std::string criterion =
      in.choice("criterion", {"body-body", "body-centre-of-mass", "both"}, "both");
  int master = 0;
  if (in.has("master")) {
    const std::string name = in.text("master");
    const auto it = std::find(body_names.begin(), body_names.end(), name);
    if (it == body_names.end())
      in.fail("master", "expected the name of a [[body]], found \"" + name + "\"");
    else
      master = static_cast<int>(it - body_names.begin());
  }
  const ReleaseCriterion c = criterion == "body-body" ? ReleaseCriterion::body_body
                             : criterion == "body-centre-of-mass"
                                 ? ReleaseCriterion::body_centre_of_mass
                                 : ReleaseCriterion::both;
  const bool hysteresis = in.flag_or("hysteresis", c == ReleaseCriterion::both);
  return std::make_unique<Release<D>>(c, master, body_names.empty() ? "" : body_names[master],
                                      hysteresis);
}

template std::unique_ptr<ContactModel<2>> make_release<2>(ParameterReader&,
                                                          const std::vector<std::string>&);
template std::unique_ptr<ContactModel<3>> make_release<3>(ParameterReader&,
                                                          const std::vector<std::string>&);

}  // namespace pellicle
