#include "pellicle/mpm/contact/contact_model.hpp"

#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

template <int D>
void ContactModel<D>::after_grid_update(Simulation<D>& simulation, GridPass pass, double dt) {
  // Normals from the colour at the start of the step serve both passes.
  if (pass == GridPass::lagrangian) shared_.colour_functions(simulation);
  resolve(simulation.fields(), simulation.points(), dt, pass);
}

template class ContactModel<2>;
template class ContactModel<3>;

}  // namespace pellicle
