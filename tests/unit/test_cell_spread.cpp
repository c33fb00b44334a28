// Spreading points onto cell centres (mpm/cell_field.hpp) for some cells only: contact's
// colour functions are read on the cells around the nodes two bodies share, and only the
// points whose spread reaches one of them spread. Those cells must hold exactly the sums of a
// spread of every point: points inside, in the cells next to fixed, slipping and free faces,
// and on the faces themselves, at one and two threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <random>
#include <vector>

#include "pellicle/mpm/cell_field.hpp"
#include "pellicle/mpm/grid.hpp"

namespace pellicle {
namespace {

template <int D>
Grid<D> mixed_faces_grid() {
  FaceConditions<D> faces;
  faces.fill(FaceCondition::fixed);
  faces[1] = FaceCondition::slip;  // x-max
  faces[2] = FaceCondition::free;  // y-min
  return Grid<D>(Vec<D>::Zero(), Vec<D>::Ones(), 1.0 / 12, faces);
}

template <int D>
void expect_read_cells_hold_full_sums(int threads) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Grid<D> grid = mixed_faces_grid<D>();
  const long cells = cell_count(grid);
  std::vector<Vec<D>> positions;
  std::vector<double> volume;
  for (int k = 0; k < 2000; ++k) {
    Vec<D> x;
    for (int d = 0; d < D; ++d) x[d] = u(rng);
    if (k % 50 == 0) x[k % D] = (k / 50) % 2 == 0 ? 0.0 : 1.0;  // on a lower or upper face
    positions.push_back(x);
    volume.push_back(0.5 + u(rng));
  }
  // Read: a few scattered cells, and the cells of a corner and of each face's first layer.
  std::vector<double> reads(cells, 0.0);
  for (int k = 0; k < 12; ++k) reads[static_cast<long>(u(rng) * cells)] = 1.0;
  reads[0] = reads[cells - 1] = 1.0;
  reads[grid.cells()[0] - 1] = 1.0;
  std::vector<char> from;
  cells_spread_from(grid, reads, from);
  long marked = 0;
  for (char f : from) marked += f;
  EXPECT_GT(marked, 0);
  EXPECT_LT(marked, cells / 2);  // most points do not spread

  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  std::vector<double> all(cells, 0.0), some(cells, 0.0);
  CellSpreadCopies work_all, work_some;
  spread_to_cells(grid, positions, volume, 0, static_cast<long>(positions.size()), all, work_all);
  spread_to_cells(grid, positions, volume, 0, static_cast<long>(positions.size()), some, work_some,
                  &from);
  omp_set_num_threads(before);
  long differ = 0;
  for (long c = 0; c < cells; ++c) {
    if (reads[c] > 0.0) {
      EXPECT_EQ(some[c], all[c]) << "cell " << c;
    }
    differ += some[c] != all[c];
  }
  EXPECT_GT(differ, 0);  // the points left out left cells that are not read incomplete
}

TEST(CellSpread, ReadCellsHoldTheFullSums) {
  for (int threads : {1, 2}) {
    expect_read_cells_hold_full_sums<2>(threads);
    expect_read_cells_hold_full_sums<3>(threads);
  }
}

//! cells_around_node gives the cells cell_gradient_at_node differences: a field that is
//! linear in the cell centres' x has the gradient (1, 0[, 0]) at an interior node.
TEST(CellSpread, CellsAroundANodeAreTheGradientsCells) {
  const Grid<2> grid = mixed_faces_grid<2>();
  std::vector<double> field(cell_count(grid));
  for (long c = 0; c < cell_count(grid); ++c)
    field[c] = (static_cast<double>(c % grid.cells()[0]) + 0.5) * grid.cell();
  const long node = grid.flatten(IVec<2>(Grid<2>::kGhost + 5, Grid<2>::kGhost + 7));
  long around[4];
  cells_around_node(grid, node, around);
  EXPECT_EQ(around[0], 4 + 6 * grid.cells()[0]);
  EXPECT_EQ(around[3], 5 + 7 * grid.cells()[0]);
  const Vec2 gradient = cell_gradient_at_node(grid, field, node);
  EXPECT_NEAR(gradient[0], 1.0, 1e-12);
  EXPECT_NEAR(gradient[1], 0.0, 1e-12);
}

}  // namespace
}  // namespace pellicle
