// Frictional contact in the manner of Bardenhagen, Brackbill & Sulsky (2000), written
// against the centre-of-mass field: at a shared node body I approaches when
// (v^I − v^cm) · n^I > 0. It then loses that normal relative velocity (no penetration) and
// at most μ times as much of its tangential relative velocity (Coulomb: the tangential
// impulse is bounded by μ times the normal one); μ = inf is no slip. A body moving away
// keeps its own velocity (free separation).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "pellicle/mpm/contact/contact_model.hpp"

namespace pellicle {
namespace {

template <int D>
class Friction final : public ContactModel<D> {
 public:
  explicit Friction(double coefficient) : mu_(coefficient) {}

  std::string describe() const override {
    char text[64];
    std::snprintf(text, sizeof text, "friction, μ = %g", mu_);
    return std::isinf(mu_) ? "friction, no slip" : text;
  }

  void resolve(GridFields<D>& fields, const Particles<D>& points, double dt,
               GridPass pass) override {
    this->shared_.sweep(fields, points, dt, pass, [this](SharedNode<D>& node) {
      use_common_normal(node);
      for (int k = 0; k < node.count; ++k) {
        const Vec<D>& n = node.normal[k];
        const Vec<D> relative = node.velocity[k] - node.centre_of_mass;
        const double approach = relative.dot(n);
        if (n.isZero() || approach <= 0.0) continue;  // separating: free
        const Vec<D> tangential = relative - approach * n;
        const double slip = tangential.norm();
        Vec<D> v = node.velocity[k] - approach * n;
        if (slip > 0.0) v -= std::min(1.0, mu_ * approach / slip) * tangential;
        node.velocity[k] = v;
      }
    });
  }

 private:
  double mu_;
};

}  // namespace

template <int D>
std::unique_ptr<ContactModel<D>> make_friction(ParameterReader& in,
                                               const std::vector<std::string>&) {
  const double mu =
      in.number("coefficient", {0.0, std::numeric_limits<double>::infinity(), false, false});
  return std::make_unique<Friction<D>>(mu);
}

template std::unique_ptr<ContactModel<2>> make_friction<2>(ParameterReader&,
                                                           const std::vector<std::string>&);
template std::unique_ptr<ContactModel<3>> make_friction<3>(ParameterReader&,
                                                           const std::vector<std::string>&);

}  // namespace pellicle
