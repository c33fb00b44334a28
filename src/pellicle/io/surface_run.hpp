#pragma once
//! Drive a surface simulation to its end time with output and progress reporting. On a
//! numerical failure the history and a final snapshot are still written, summary.json
//! records the failure, and the NumericalError is rethrown (exit code 3).

#include <string>

#include "pellicle/core/progress.hpp"
#include "pellicle/io/run.hpp"
#include "pellicle/io/surface_output.hpp"

namespace pellicle {

template <int D>
RunStatistics run_surface_simulation(SurfaceSimulation<D>& simulation,
                                     SurfaceOutputWriter<D>& output, ProgressListener* progress,
                                     const std::string& case_hash);

}  // namespace pellicle
