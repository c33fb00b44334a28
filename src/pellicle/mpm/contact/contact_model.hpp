#pragma once
//! Contact models: how bodies that share grid nodes interact. Without one, every body moves
//! in the single centre-of-mass velocity field (automatic no-slip, no-penetration contact,
//! IJNME §2). A model is a step hook: it gives each body its own grid field (GridFields)
//! and, after each grid update, decides node by node (SharedNodes)
//! which velocity each body takes: the contact-release criteria of York (IJNME eq 26,
//! thesis eqs 9.7–9.9) or Coulomb friction (Bardenhagen, Brackbill & Sulsky 2000).
//! Chosen by name in the case's [contact] table (registry.cpp).

#include <memory>
#include <string>
#include <vector>

#include "pellicle/core/parameters.hpp"
#include "pellicle/mpm/contact/shared_nodes.hpp"
#include "pellicle/mpm/step_hook.hpp"

namespace pellicle {

template <int D>
class ContactModel : public StepHook<D> {
 public:
  bool needs_body_fields() const override { return true; }
  //! Set each body's velocity at every node it shares with others: after the grid solve
  //! (Lagrangian pass) and again on the convected velocities of the MUSL remap.
  void after_grid_update(Simulation<D>& simulation, GridPass pass, double dt) override;
  //! One line for run summaries, e.g. "release, criterion both".
  virtual std::string describe() const = 0;
  //! Total contact force on each body in the last step.
  const std::vector<Vec<D>>& contact_forces() const { return shared_.contact_force(); }

 protected:
  virtual void resolve(GridFields<D>& fields, const Particles<D>& points, double dt,
                       GridPass pass) = 0;
  SharedNodes<D> shared_;
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
