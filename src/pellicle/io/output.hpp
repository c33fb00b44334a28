#pragma once
//! The files of a run, in its output directory:
//!   history.csv   time series of energies, momentum and per-body centre of mass/velocity,
//!                 flushed at every row
//!   points.pvd    ParaView series of particle snapshots points_NNNNNN.vtu
//!   grid.pvd      (optional) series of grid snapshots grid_NNNNNN.vti, with the point
//!                 stresses projected onto the nodes when each is written
//!   summary.json  final values, version, case hash, wall time, throughput, status

#include <chrono>
#include <fstream>
#include <memory>
#include <string>

#include "pellicle/io/case.hpp"
#include "pellicle/io/probes.hpp"
#include "pellicle/io/vtk_writer.hpp"
#include "pellicle/mpm/grid_projection.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

template <int D>
class OutputWriter final : public StepObserver<D> {
 public:
  //! Creates the directory, writes the history header, the t = 0 row and snapshot. Bodies that
  //! fill a membrane add <membrane>.enclosed_volume, <membrane>.tension and <filler>.escaped.
  OutputWriter(const OutputSettings& settings, const Simulation<D>& simulation,
               std::vector<Probe<D>> probes = {});

  void after_step(const Simulation<D>& simulation) override;
  //! Final row and snapshot (if not just written) and summary.json. `status` is "completed"
  //! or the failure message.
  void finish(const Simulation<D>& simulation, const std::string& status,
              const std::string& case_hash, double wall_seconds);

  const std::string& directory() const { return settings_.directory; }

 private:
  void write_history_row(const Simulation<D>& simulation);
  void write_snapshot(const Simulation<D>& simulation);
  //! A distributed run's grid snapshot: this rank's piece, and on rank 0 the .pvti that joins
  //! them (its name left in `name`).
  void write_grid_pieces(const Simulation<D>& simulation, const NodeStresses<D>& stresses,
                         char* name, std::size_t size);

  OutputSettings settings_;
  std::vector<Probe<D>> probes_;
  std::ofstream history_;
  PvdCollection points_series_, grid_series_;
  GridProjection<D> projection_;  //!< used only for grid snapshots
  double next_history_ = 0.0, next_snapshot_ = 0.0;
  long last_history_step_ = -1, last_snapshot_step_ = -1;
  int snapshots_ = 0;
  int rank_ = 0, ranks_ = 1;   //!< of a distributed run; rank 0 writes all but the pieces
  std::vector<long> escaped_;  //!< per enclosed body: most filling points seen outside
};

//! 16 hex digits of the FNV-1a 64-bit hash of a text (identifies the case that was run).
std::string hash_text(const std::string& text);

extern template class OutputWriter<2>;
extern template class OutputWriter<3>;

}  // namespace pellicle
