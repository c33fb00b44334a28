#pragma once
//! VTK XML output for ParaView: particle snapshots (.vtu, inline binary), grid snapshots
//! (.vti) and the .pvd collections that index them by time.

#include <string>
#include <vector>

#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/grid_projection.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

//! Particle snapshot: positions and velocity, mass, volume, density, stress, strain,
//! pressure, von Mises stress, body id and whether the point is a fluid's, per point.
//! Written atomically, streamed a few thousand points at a time (its memory does not grow
//! with the number of points).
template <int D>
void write_points_vtu(const std::string& path, const Simulation<D>& simulation);

//! A distributed run's particle snapshot: the file that joins the ranks' pieces (each a
//! write_points_vtu of that rank's points, named relative to the .pvtu) and declares their
//! arrays, the same arrays write_points_vtu writes.
template <int D>
void write_points_pvtu(const std::string& path, const Simulation<D>& simulation,
                       const std::vector<std::string>& pieces);

//! Grid snapshot on the node lattice (ghost layers included): nodal mass and velocity, and
//! the point stresses projected onto the nodes (grid_projection.hpp): `pressure`, `stress`
//! and `membrane_stress`, tensors as ParaView's 6-component symmetric tensors.
//! The nodes `first` to `last` (grid indices; default all stored) in the grid's index space,
//! so a distributed run's pieces fit together.
template <int D>
void write_grid_vti(const std::string& path, const Grid<D>& grid, const NodeStresses<D>& stresses,
                    const IVec<D>& first, const IVec<D>& last);
template <int D>
void write_grid_vti(const std::string& path, const Grid<D>& grid, const NodeStresses<D>& stresses) {
  const IVec<D> last = grid.first() + grid.nodes() - IVec<D>::Ones();
  write_grid_vti<D>(path, grid, stresses, grid.first(), last);
}

//! A distributed run's grid snapshot: the file that joins the ranks' pieces (each a
//! write_grid_vti of that rank's nodes, piece r's nodes `first[r]` to `last[r]`, named
//! relative to the .pvti) and declares their arrays.
template <int D>
void write_grid_pvti(const std::string& path, const Grid<D>& grid,
                     const std::vector<std::string>& pieces, const std::vector<IVec<D>>& first,
                     const std::vector<IVec<D>>& last);

//! A time series of files for ParaView.
class PvdCollection {
 public:
  explicit PvdCollection(std::string path) : path_(std::move(path)) {}
  //! Add an entry (file relative to the .pvd) and rewrite the collection atomically.
  void add(double time, const std::string& file);

 private:
  std::string path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace pellicle
