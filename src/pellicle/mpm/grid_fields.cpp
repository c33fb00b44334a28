#include "pellicle/mpm/grid_fields.hpp"

namespace pellicle {

template <int D>
void GridFields<D>::sum_to_centre_of_mass(bool mass, bool forces) {
  if (!per_body()) return;
  if (mass) {  // the step's first sums: the bodies' live nodes are the sum's
    live_sum_ = body_grids_[0].live();
    for (const auto& g : body_grids_)
      for (std::size_t r = 0; r < live_sum_.size(); ++r)
        live_sum_[r].add(g.live()[r].first, g.live()[r].last);
    centre_of_mass_.restart_live(live_sum_);
  }
  centre_of_mass_.for_each_live([&](long n) {
    double m = 0.0;
    Vec<D> momentum = Vec<D>::Zero(), force = Vec<D>::Zero();
    for (const auto& g : body_grids_) {
      if (mass) m += g.mass[n];
      momentum += g.momentum[n];
      if (forces) force += g.force[n];
    }
    if (mass) centre_of_mass_.mass[n] = m;
    centre_of_mass_.momentum[n] = momentum;
    if (forces) centre_of_mass_.force[n] = force;
  });
}

template <int D>
std::size_t GridFields<D>::bytes_per_node() const {
  return (1 + body_grids_.size()) * (sizeof(double) + 4 * sizeof(Vec<D>));
}

template class GridFields<2>;
template class GridFields<3>;

}  // namespace pellicle
