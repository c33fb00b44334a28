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
//! cell_count() entries.
template <int D>
void spread_to_cells(const Grid<D>& grid, const std::vector<Vec<D>>& positions,
                     const std::vector<double>& weight, long begin, long end,
                     std::vector<double>& cells, CellSpreadCopies& work);
//! Gradient at grid node `node` of the cell field interpolated bilinearly (trilinearly)
//! between cell centres (the MPM gradient operator on the dual grid, IJNME eq 28). Cells
//! beyond a constrained face mirror the inside, beyond a free face they are empty.
template <int D>
Vec<D> cell_gradient_at_node(const Grid<D>& grid, const std::vector<double>& cells, long node);

}  // namespace pellicle
