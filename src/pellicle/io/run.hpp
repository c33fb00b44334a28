#pragma once
//! The one run pipeline of both engines (MPM Simulation<D>, SurfaceSimulation<D>): step to
//! the end time with an output writer and a progress listener attached, write checkpoints
//! where the engine has them, and stop cleanly on a signal. On a numerical failure the
//! history and a final snapshot are still written, summary.json records the failure, and
//! the NumericalError is rethrown for the caller to report (exit code 3).
//!
//! An engine has step(), finished(), time(), step_count(), point_count(), last_dt(),
//! settings().end_time and add_observer/remove_observer(RunObserver<Engine>*); its output
//! writer is a RunObserver<Engine> with finish(engine, status, case_hash, wall_seconds).

#include <csignal>
#include <functional>
#include <string>

#include "pellicle/core/collective.hpp"
#include "pellicle/core/progress.hpp"

namespace pellicle {

//! Checkpoints and interruption of a run.
struct RunControl {
  std::string case_hash;  //!< identifies the case in summary.json
  //! Writes a checkpoint of the run's current state; empty: the run writes none.
  std::function<void()> checkpoint;
  double checkpoint_interval = 0.0;  //!< simulated time between them; 0: only when stopped
  //! Set (to the signal number) by a signal handler: the run stops after the current step,
  //! writes a final checkpoint and its summary with status "interrupted".
  const volatile std::sig_atomic_t* stop = nullptr;
  //! A distributed run's ranks: they agree on a stop signal after every step (a signal
  //! reaches them at different moments), so all stop after the same step.
  const Collective* ranks = nullptr;
};

struct RunStatistics {
  double wall_seconds = 0.0;
  double particle_steps_per_second = 0.0;
  int interrupted_by = 0;  //!< the signal that stopped the run, or 0
};

template <class Engine, class Output>
RunStatistics run_simulation(Engine& engine, Output& output, ProgressListener* progress,
                             const RunControl& control);

}  // namespace pellicle
