#include "pellicle/mpm/cell_density.hpp"

#include <cmath>
#include <numbers>

#include "pellicle/mpm/cell_field.hpp"

namespace pellicle {

template <int D>
void cell_quadratic_density(const Grid<D>& grid, bool axisymmetric,
                            const std::vector<std::pair<long, long>>& ranges, Particles<D>& points,
                            const std::function<void(std::vector<double>&)>& complete,
                            CellDensityWork& work) {
  // Eq 4.6: M_c = Σ_p m_p S(x_c − x_p), S the quadratic B-spline on cell centres.
  std::vector<double>& cell_mass = work.cell_mass;
  cell_mass.assign(cell_count(grid), 0.0);
  for (const auto& [begin, end] : ranges)
    spread_to_cells(grid, points.position, points.mass, begin, end, cell_mass, work.copies);
  complete(cell_mass);

  // Eq 4.5: each point takes the density of its cell.
  const double h = grid.cell(), cell_volume = std::pow(h, D);
  for (const auto& [begin, end] : ranges) {
#pragma omp parallel for schedule(static)
    for (long p = begin; p < end; ++p) {
      const long cell = containing_cell(grid, points.position[p]);
      double volume = cell_volume;
      if (axisymmetric) {
        const long column = cell % grid.cells()[0];
        volume *= 2.0 * std::numbers::pi * (grid.lower()[0] + (column + 0.5) * h);
      }
      points.density[p] = cell_mass[cell] / volume;
      points.volume[p] = points.mass[p] / points.density[p];
    }
  }
}

template void cell_quadratic_density<2>(const Grid<2>&, bool,
                                        const std::vector<std::pair<long, long>>&, Particles<2>&,
                                        const std::function<void(std::vector<double>&)>&,
                                        CellDensityWork&);
template void cell_quadratic_density<3>(const Grid<3>&, bool,
                                        const std::vector<std::pair<long, long>>&, Particles<3>&,
                                        const std::function<void(std::vector<double>&)>&,
                                        CellDensityWork&);

}  // namespace pellicle
