#pragma once
//! Point stresses projected onto the grid nodes, for grid snapshots. The thesis shows the
//! pressure of the gas and the stress of the membrane around it as contours on the grid,
//! "interpolated to grid points from material points" (thesis §6.2.4, Fig 56); this is that
//! interpolation, with the run's own kernel: a mass-weighted mean over the points whose
//! kernel reaches node i,
//!   q_i = Σ_p N_i(x_p) m_p q_p / Σ_p N_i(x_p) m_p,
//! over the points of one kind only (fluid, membrane) or of every kind, and zero at nodes no
//! such point reaches. A mean rather than the sum Σ N m q / m_i of the step's transfers, so
//! a uniform state projects to itself at every node a point reaches (walls and ghost nodes
//! included: nothing is folded onto mirrored nodes).
//!
//! It runs only when a grid snapshot is written, never in the step: its work arrays are
//! members, sized at the first snapshot and reused.

#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

//! Node fields of a grid snapshot, one entry per node of the grid (ghost layers included).
template <int D>
struct NodeStresses {
  //! Pressure of the fluid points, p_p = −tr σ_p / 3 (the stored stress keeps zz in 2D, so
  //! this is the pressure in 2D too, including the artificial viscosity q); zero at nodes no
  //! fluid point reaches.
  std::vector<double> pressure;
  //! Cauchy stress of every point, in the points' stored order (types.hpp).
  std::vector<Sym<D>> stress;
  //! Cauchy stress (global axes) of the membrane points only: the membrane stress contours
  //! of thesis Fig 56; zero at nodes no membrane point reaches.
  std::vector<Sym<D>> membrane_stress;
};

template <int D>
class GridProjection {
 public:
  //! Project the points' stresses, at their current positions, onto the nodes of the
  //! simulation's centre-of-mass grid with its transfer's kernel. Fluid and membrane points
  //! are those whose material says is_fluid() or is_membrane(). Parallel over points; each
  //! thread sums into its own node arrays, added up afterwards (no races, and the same
  //! result for the same thread count). The result stays valid until the next call.
  const NodeStresses<D>& project(const Simulation<D>& simulation);

 private:
  //! Σ N m per node over all, fluid and membrane points, and the Σ N m q of each field.
  struct Sums {
    std::vector<double> mass, fluid_mass, membrane_mass;
    NodeStresses<D> fields;
  };
  void prepare(int threads, long nodes, int stencil);

  static constexpr long kBlock = 64;   //!< points per call of Transfer::node_weights
  std::vector<Sums> sums_;             //!< one per thread; thread 0's become the means
  std::vector<long> block_nodes_;      //!< per thread: kBlock stencils of node ids
  std::vector<double> block_weights_;  //!< and their weights
  std::vector<unsigned char> body_kind_;
};

extern template class GridProjection<2>;
extern template class GridProjection<3>;

}  // namespace pellicle
