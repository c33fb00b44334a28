#pragma once
//! The files of a surface run, in its output directory:
//!   history.csv    time, step, points N(t), points added/merged/removed so far, linear
//!                  solver iterations and residual, the area Σ A_i and (with a PDE) the
//!                  integral Σ A_i φ_i (quadrature.hpp), errors against the exact solution
//!                  (eq 34) when the case gives one, and the mean of each monitor formula;
//!                  flushed at every row
//!   surface.pvd    ParaView series of snapshots surface_NNNNNN.vtp (points, normals,
//!                  velocity, smoothing length, boundary flag, curvature, every field)
//!   summary.json   final values, version, case hash, wall time, status

#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "pellicle/io/case.hpp"
#include "pellicle/io/vtk_writer.hpp"
#include "pellicle/surface/simulation.hpp"

namespace pellicle {

//! Snapshot of the cloud, written atomically.
template <int D>
void write_surface_vtp(const std::string& path, const SurfaceSimulation<D>& s);

template <int D>
class SurfaceOutputWriter final : public SurfaceObserver<D> {
 public:
  //! Creates the directory, writes the history header, the t = 0 row and snapshot.
  SurfaceOutputWriter(const OutputSettings& settings, const SurfaceSimulation<D>& s,
                      std::vector<std::pair<std::string, PointFormula>> monitors);
  void after_step(const SurfaceSimulation<D>& s) override;
  //! Final row and snapshot (if not just written) and summary.json.
  void finish(const SurfaceSimulation<D>& s, const std::string& status,
              const std::string& case_hash, double wall_seconds);
  const std::string& directory() const { return settings_.directory; }

 private:
  void write_row(const SurfaceSimulation<D>& s);
  void write_snapshot(const SurfaceSimulation<D>& s);

  OutputSettings settings_;
  std::vector<std::pair<std::string, PointFormula>> monitors_;
  std::ofstream history_;
  PvdCollection series_;
  double next_row_ = 0.0, next_snapshot_ = 0.0;
  long last_row_ = -1, last_snapshot_ = -1;
  int snapshots_ = 0;
  std::vector<double> areas_;
};

extern template class SurfaceOutputWriter<2>;
extern template class SurfaceOutputWriter<3>;

}  // namespace pellicle
