#include "pellicle/mpm/cell_density.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pellicle/core/bspline.hpp"

namespace pellicle {

namespace {

//! Cell index along one axis after reflection at a constrained face; −1 when the mass leaves
//! through a free face.
int fold_cell(int i, int cells, FaceCondition low, FaceCondition high) {
  if (i < 0) return low == FaceCondition::free ? -1 : -1 - i;
  if (i >= cells) return high == FaceCondition::free ? -1 : 2 * cells - 1 - i;
  return i;
}

}  // namespace

template <int D>
void cell_quadratic_density(const Grid<D>& grid, bool axisymmetric,
                            const std::vector<std::pair<long, long>>& ranges,
                            Particles<D>& points) {
  const IVec<D>& cells = grid.cells();
  const auto& faces = grid.faces();
  const double h = grid.cell();
  long cell_count = 1;
  std::array<long, D> stride{};
  for (int d = 0; d < D; ++d) stride[d] = cell_count, cell_count *= cells[d];
  std::vector<double> cell_mass(cell_count, 0.0);

  // Eq 4.6: M_c = Σ_p m_p S(x_c − x_p), S the quadratic B-spline on cell centres.
  for (const auto& [begin, end] : ranges) {
#pragma omp parallel for schedule(static)
    for (long p = begin; p < end; ++p) {
      const Vec<D> centre_units = (points.position[p] - grid.lower()) / h - Vec<D>::Constant(0.5);
      double w[D][3], dw[3];
      int base[D];
      for (int d = 0; d < D; ++d) base[d] = quadratic_bspline(centre_units[d], w[d], dw);
      for (int k = 0; k < (D == 3 ? 3 : 1); ++k)
        for (int j = 0; j < 3; ++j)
          for (int i = 0; i < 3; ++i) {
            const int offset[3] = {i, j, k};
            long flat = 0;
            double weight = points.mass[p];
            for (int d = 0; d < D; ++d) {
              const int c =
                  fold_cell(base[d] + offset[d], cells[d], faces[2 * d], faces[2 * d + 1]);
              if (c < 0) weight = 0.0;
              flat += (c < 0 ? 0 : c) * stride[d];
              weight *= w[d][offset[d]];
            }
            if (weight == 0.0) continue;
#pragma omp atomic
            cell_mass[flat] += weight;
          }
    }
  }

  // Eq 4.5: each point takes the density of its cell.
  const double cell_volume = std::pow(h, D);
  for (const auto& [begin, end] : ranges) {
#pragma omp parallel for schedule(static)
    for (long p = begin; p < end; ++p) {
      long flat = 0;
      double radius = 0.0;
      for (int d = 0; d < D; ++d) {
        const int c =
            std::clamp(static_cast<int>(std::floor((points.position[p][d] - grid.lower()[d]) / h)),
                       0, cells[d] - 1);
        flat += c * stride[d];
        if (d == 0) radius = grid.lower()[0] + (c + 0.5) * h;
      }
      const double volume =
          axisymmetric ? 2.0 * std::numbers::pi * radius * cell_volume : cell_volume;
      points.density[p] = cell_mass[flat] / volume;
      points.volume[p] = points.mass[p] / points.density[p];
    }
  }
}

template void cell_quadratic_density<2>(const Grid<2>&, bool,
                                        const std::vector<std::pair<long, long>>&, Particles<2>&);
template void cell_quadratic_density<3>(const Grid<3>&, bool,
                                        const std::vector<std::pair<long, long>>&, Particles<3>&);

}  // namespace pellicle
