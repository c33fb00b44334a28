#include "pellicle/mpm/boundary/rigid_bodies.hpp"

#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

template <int D>
void RigidBodies<D>::after_to_grid(Simulation<D>& simulation) {
  auto& fields = simulation.fields();
  const auto& points = simulation.points();
  auto& all = prescribed_;
  all.clear();
  for (std::size_t r = 0; r < bodies_.size(); ++r) {
    const auto& body = points.bodies[bodies_[r]];
    nodes_.clear();
    simulation.transfer().touched_nodes(fields.centre_of_mass(), body.begin, body.end, nodes_);
    const std::size_t first = all.size();
    for (long n : nodes_) all.emplace_back(n, velocity_[r]);
    if (fields.per_body())
      fields.field(bodies_[r]).prescribe(all.data() + first, all.data() + all.size());
  }
  fields.centre_of_mass().prescribe(all);
}

template <int D>
void RigidBodies<D>::after_to_points(Simulation<D>& simulation) {
  auto& points = simulation.points();
  for (std::size_t r = 0; r < bodies_.size(); ++r) {
    const auto& body = points.bodies[bodies_[r]];
    for (long p = body.begin; p < body.end; ++p) points.velocity[p] = velocity_[r];
  }
}

template class RigidBodies<2>;
template class RigidBodies<3>;

}  // namespace pellicle
