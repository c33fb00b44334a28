#pragma once
//! Drive a simulation to its end time with output and progress reporting. On a numerical
//! failure the history and a final snapshot are still written, summary.json records the
//! failure, and the NumericalError is rethrown for the caller to report (exit code 3).

#include <string>

#include "pellicle/core/progress.hpp"
#include "pellicle/io/output.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

struct RunStatistics {
  double wall_seconds = 0.0;
  double particle_steps_per_second = 0.0;
};

template <int D>
RunStatistics run_simulation(Simulation<D>& simulation, OutputWriter<D>& output,
                             ProgressListener* progress, const std::string& case_hash);

}  // namespace pellicle
