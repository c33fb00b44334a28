#pragma once
//! Drive a simulation to its end time with output and progress reporting. On a numerical
//! failure the history and a final snapshot are still written, summary.json records the
//! failure, and the NumericalError is rethrown for the caller to report (exit code 3).

#include <csignal>
#include <string>

#include "pellicle/core/progress.hpp"
#include "pellicle/io/checkpoint.hpp"
#include "pellicle/io/output.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

//! Checkpoints and interruption of a run.
struct RunControl {
  CheckpointHeader header;           //!< identifies the case in checkpoints and summary.json
  std::string checkpoint_path;       //!< where checkpoints go; empty: none are written
  double checkpoint_interval = 0.0;  //!< simulated time between them; 0: only when stopped
  //! Set (to the signal number) by a signal handler: the run stops after the current step,
  //! writes a final checkpoint and its summary with status "interrupted".
  const volatile std::sig_atomic_t* stop = nullptr;
};

struct RunStatistics {
  double wall_seconds = 0.0;
  double particle_steps_per_second = 0.0;
  int interrupted_by = 0;  //!< the signal that stopped the run, or 0
};

template <int D>
RunStatistics run_simulation(Simulation<D>& simulation, OutputWriter<D>& output,
                             ProgressListener* progress, const RunControl& control);

}  // namespace pellicle
