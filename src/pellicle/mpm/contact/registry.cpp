//! The contact registry: adding a model is one new file and one line here.
#include "pellicle/mpm/contact/contact_model.hpp"

namespace pellicle {

template <int D>
const std::vector<ContactChoice<D>>& contact_models() {
  static const std::vector<ContactChoice<D>> models = {
      {"release", "York's contact-release: no-slip contact, free release (thesis eqs 9.7–9.9)",
       &make_release<D>},
      {"friction", "Coulomb friction, free separation (Bardenhagen, Brackbill & Sulsky 2000)",
       &make_friction<D>},
  };
  return models;
}

template const std::vector<ContactChoice<2>>& contact_models<2>();
template const std::vector<ContactChoice<3>>& contact_models<3>();

}  // namespace pellicle
