#pragma once
//! Fields on the grid's cell centres, spread from points with the tensor-product quadratic
//! B-spline S (thesis eqs 4.6 and 9.10; IJNME eq 27). Used for cell densities of fluids and
//! for the colour function whose gradient gives each body's grid normals (IJNME eq 28).
//! A point's weight spread beyond a wall or symmetry face is reflected into the mirror cell;
//! beyond a free face it is lost.

#include <utility>
#include <vector>

#include "pellicle/mpm/grid.hpp"

namespace pellicle {

template <int D>
long cell_count(const Grid<D>& grid);
//! Flat index of the cell that contains x (clamped to the domain).
template <int D>
long containing_cell(const Grid<D>& grid, const Vec<D>& x);
//! Work arrays of spread_to_cells: a private copy of the cell field for each thread beyond
//! the first, kept zeroed between calls so a step allocates nothing.
struct CellSpreadCopies {
  std::vector<std::vector<double>> copies;
  std::vector<std::pair<long, long>> written;  //!< per copy, the cells a spread wrote to
};
//! cells[c] += Σ_p weight[p] S(x_c − x_p) over the points [begin, end); `cells` must have
//! cell_count() entries. With `from` (cell_count() entries, from cells_spread_from), only
//! the points whose first cell is marked in it spread: the cells their spread reaches hold
//! the full sums, the others partial ones.
template <int D>
void spread_to_cells(const Grid<D>& grid, const std::vector<Vec<D>>& positions,
                     const std::vector<double>& weight, long begin, long end,
                     std::vector<double>& cells, CellSpreadCopies& work,
                     const std::vector<char>* from = nullptr);
//! The cells a point may spread from, for the values of the cells with reads[c] > 0 only:
//! from[f] = 1 for every first cell f (per axis the first of the point's three cells, −1 to
//! cells − 2, stored shifted by one) whose three cells per axis reach, after folding at the
//! faces, a cell read; 0 for all others. `from` is resized to cell_count().
template <int D>
void cells_spread_from(const Grid<D>& grid, const std::vector<double>& reads,
                       std::vector<char>& from);
//! The flat indices of the 2^D cells around grid node `node` (axis-0 bit first), after
//! folding at the faces; −1 beyond a free face. The cells cell_gradient_at_node reads.
template <int D>
void cells_around_node(const Grid<D>& grid, long node, long (&cells)[1 << D]);
//! Gradient at grid node `node` of the cell field interpolated bilinearly (trilinearly)
//! between cell centres (the MPM gradient operator on the dual grid, IJNME eq 28). Cells
//! beyond a constrained face mirror the inside, beyond a free face they are empty.
template <int D>
Vec<D> cell_gradient_at_node(const Grid<D>& grid, const std::vector<double>& cells, long node);

}  // namespace pellicle
