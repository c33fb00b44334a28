#pragma once
//! Point densities from cell densities (thesis eqs 4.5–4.6): the mass of the points is spread
//! to cell centres with the quadratic B-spline, each cell's density is that mass over the
//! cell's volume, and every point takes the density of the cell that contains it. An
//! alternative to the continuity equation (eq 4.7) for fluids; smoother across a shock than
//! counting the mass in each cell (docs/theory/gas.md).

#include <functional>
#include <utility>
#include <vector>

#include "pellicle/mpm/cell_field.hpp"
#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/particles.hpp"

namespace pellicle {

//! Work arrays of cell_quadratic_density, kept by its caller from step to step.
struct CellDensityWork {
  std::vector<double> cell_mass;
  CellSpreadCopies copies;
};

//! Set density and volume of the points in `ranges` (each [begin, end)) from the mass of all
//! of them. Mass spread beyond a wall or symmetry face is reflected back into the domain;
//! beyond a free face it is lost (the fluid meets vacuum there). `axisymmetric`: cell
//! volumes are 2π r_c h² and masses are per radian × 2π, as the points' are. `complete`
//! completes the cell masses spread from these points (a distributed run's cell sums).
template <int D>
void cell_quadratic_density(const Grid<D>& grid, bool axisymmetric,
                            const std::vector<std::pair<long, long>>& ranges, Particles<D>& points,
                            const std::function<void(std::vector<double>&)>& complete,
                            CellDensityWork& work);

}  // namespace pellicle
