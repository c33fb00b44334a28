#include "pellicle/mpm/contact/shared_nodes.hpp"

#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

template <int D>
void SharedNodes<D>::colour_functions(Simulation<D>& simulation) {
  // Eq 27 / 9.10 with each point's colour its volume: the colour function is a smoothed
  // volume of its body per cell (its scale does not matter, only its gradient's direction).
  const GridFields<D>& fields = simulation.fields();
  const Particles<D>& points = simulation.points();
  colour_.resize(fields.count());
  for (int b = 0; b < fields.count(); ++b) {
    const auto& body = points.bodies[b];
    std::vector<double>& colour = colour_[b];
    const long cells = cell_count(fields.field(b));
    colour.resize(cells);
    // Cleared by all threads: a whole-field clear on one thread holds the others up.
#pragma omp parallel for schedule(static)
    for (long c = 0; c < cells; ++c) colour[c] = 0.0;
    spread_to_cells(fields.field(b), points.position, points.volume, body.begin, body.end, colour,
                    spread_copies_);
    simulation.complete_cell_sums(colour);
  }
}

template <int D>
Vec<D> SharedNodes<D>::outward_normal(const Grid<D>& grid, int body, long node) const {
  // Eq 28 / 9.11: the colour falls off outward, so the outward normal is −∇χ / |∇χ|.
  const Vec<D> gradient = cell_gradient_at_node(grid, colour_[body], node);
  const double length = gradient.norm();
  return length > 0.0 ? Vec<D>(-gradient / length) : Vec<D>::Zero();
}

template class SharedNodes<2>;
template class SharedNodes<3>;

}  // namespace pellicle
