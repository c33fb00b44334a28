#include "pellicle/mpm/contact/shared_nodes.hpp"

#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

template <int D>
void SharedNodes<D>::colour_functions(Simulation<D>& simulation) {
  GridFields<D>& fields = simulation.fields();
  const Particles<D>& points = simulation.points();
  const Grid<D>& grid = fields.centre_of_mass();
  const long cells = cell_count(grid);
  point_at_fields(fields);
  // Only the cells the sweeps read need a colour (eq 28 at the nodes two or more bodies
  // share). They are marked, the marks completed by the hooks (a distributed run's neighbour
  // may read cells this rank's points spread to), and only the points whose spread reaches a
  // marked cell spread.
  reads_.resize(cells);
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (long c = 0; c < cells; ++c) reads_[c] = 0.0;
    grid.for_each_live_of_thread([&](long n) {
      if (!shared(n)) return;
      long around[1 << D];
      cells_around_node(grid, n, around);
      for (long c : around) {
        if (c < 0) continue;
#pragma omp atomic write
        reads_[c] = 1.0;
      }
    });
  }
  simulation.complete_cell_sums(reads_);
  cells_spread_from(grid, reads_, spread_from_);
  // Eq 27 / 9.10 with each point's colour its volume: the colour function is a smoothed
  // volume of its body per cell (its scale does not matter, only its gradient's direction).
  colour_.resize(fields.count());
  for (int b = 0; b < fields.count(); ++b) {
    const auto& body = points.bodies[b];
    std::vector<double>& colour = colour_[b];
    colour.resize(cells);
    // Cleared by all threads: a whole-field clear on one thread holds the others up.
#pragma omp parallel for schedule(static)
    for (long c = 0; c < cells; ++c) colour[c] = 0.0;
    spread_to_cells(fields.field(b), points.position, points.volume, body.begin, body.end, colour,
                    spread_copies_, &spread_from_);
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
