#pragma once
//! VTK XML output for ParaView: particle snapshots (.vtu, inline binary), grid snapshots
//! (.vti) and the .pvd collections that index them by time.

#include <string>
#include <vector>

#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

//! Particle snapshot: positions and velocity, mass, volume, density, stress, strain,
//! pressure, von Mises stress and body id per point. Written atomically.
template <int D>
void write_points_vtu(const std::string& path, const Simulation<D>& simulation);

//! Grid snapshot: nodal mass and velocity on the node lattice (ghost layers included).
template <int D>
void write_grid_vti(const std::string& path, const Grid<D>& grid);

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
