#pragma once
//! Contact models: how bodies that share grid nodes interact. Without one, every body moves
//! in the single centre-of-mass velocity field (automatic no-slip, no-penetration contact,
//! IJNME §2). A model gives each body its own field (BodyFields) and decides, node by node,
//! which velocity each body takes: the contact-release criteria of York (IJNME eq 26,
//! thesis eqs 9.7–9.9) or Coulomb friction (Bardenhagen, Brackbill & Sulsky 2000).
//! Chosen by name in the case's [contact] table (registry.cpp).

#include <memory>
#include <string>
#include <vector>

#include "pellicle/core/parameters.hpp"
#include "pellicle/mpm/contact/body_fields.hpp"

namespace pellicle {

template <int D>
class ContactModel {
 public:
  virtual ~ContactModel() = default;
  //! Set each body's velocity at every node it shares with others: after the grid solve
  //! (Lagrangian pass) and again on the convected velocities of the MUSL remap.
  virtual void resolve(BodyFields<D>& fields, const Grid<D>& centre_of_mass,
                       const Particles<D>& points, double dt, ContactPass pass) const = 0;
  //! One line for run summaries, e.g. "release, criterion both".
  virtual std::string describe() const = 0;
};

//! Builds a model from the [contact] table; `body_names` lets it refer to bodies.
template <int D>
using ContactFactory = std::unique_ptr<ContactModel<D>> (*)(
    ParameterReader& parameters, const std::vector<std::string>& body_names);

template <int D>
struct ContactChoice {
  std::string name;
  std::string summary;
  ContactFactory<D> make;
};

//! Registered contact models; "single-field" (no model) is handled by the case reader.
template <int D>
const std::vector<ContactChoice<D>>& contact_models();

template <int D>
std::unique_ptr<ContactModel<D>> make_release(ParameterReader&, const std::vector<std::string>&);
template <int D>
std::unique_ptr<ContactModel<D>> make_friction(ParameterReader&, const std::vector<std::string>&);

}  // namespace pellicle
