#include "pellicle/mpm/boundary/rigid_bodies.hpp"

#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

template <int D>
void RigidBodies<D>::after_to_grid(Simulation<D>& simulation) {
  auto& fields = simulation.fields();
  const auto& points = simulation.points();
  const int rigid = static_cast<int>(bodies_.size());
  // A distributed run: a node this rank holds may be touched only by another rank's points
  // of a rigid body. Each rank marks the nodes its points touch, the marks are summed over
  // the ranks that hold a node, and every marked node is prescribed.
  const bool distributed = simulation.collective() != nullptr;
  const long nodes = fields.centre_of_mass().node_count();
  if (distributed) marks_.assign(nodes * rigid, 0.0);
  touched_.resize(rigid);
  for (int r = 0; r < rigid; ++r) {
    const auto& body = points.bodies[bodies_[r]];
    touched_[r].clear();
    simulation.transfer().touched_nodes(fields.centre_of_mass(), body.begin, body.end, touched_[r]);
    if (distributed)
      for (long n : touched_[r]) marks_[n * rigid + r] = 1.0;
  }
  if (distributed) {
    simulation.complete_node_sums({{marks_.data(), rigid}});
    for (int r = 0; r < rigid; ++r) {
      touched_[r].clear();
      for (long n = 0; n < nodes; ++n)
        if (marks_[n * rigid + r] > 0.0) touched_[r].push_back(n);
    }
  }
  auto& all = prescribed_;
  all.clear();
  for (int r = 0; r < rigid; ++r) {
    const std::size_t first = all.size();
    for (long n : touched_[r]) all.emplace_back(n, velocity_[r]);
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
