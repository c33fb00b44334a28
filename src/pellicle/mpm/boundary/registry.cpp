//! The boundary-condition registry: adding one is a new file and one line here.
#include "pellicle/mpm/boundary/boundary_condition.hpp"
#include "pellicle/mpm/boundary/prescribed_velocity.hpp"

namespace pellicle {

template <int D>
const std::vector<BoundaryModel<D>>& boundary_models() {
  static const std::vector<BoundaryModel<D>> models = {
      {"prescribed-velocity", "grid nodes in a box move with a given velocity (clamp, grip)",
       &make_prescribed_velocity<D>},
  };
  return models;
}

template const std::vector<BoundaryModel<2>>& boundary_models<2>();
template const std::vector<BoundaryModel<3>>& boundary_models<3>();

}  // namespace pellicle
