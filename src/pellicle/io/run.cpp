#include "pellicle/io/run.hpp"

#include <chrono>
#include <limits>

#include "pellicle/core/error.hpp"
#include "pellicle/io/output.hpp"
#include "pellicle/io/progress_observer.hpp"
#include "pellicle/io/surface_output.hpp"

namespace pellicle {

template <class Engine, class Output>
RunStatistics run_simulation(Engine& engine, Output& output, ProgressListener* progress,
                             const RunControl& control) {
  const auto start = std::chrono::steady_clock::now();
  ProgressObserver<Engine> observer(progress, start);
  engine.add_observer(&output);
  engine.add_observer(&observer);
  struct Detach {  // the observers live only as long as this call
    Engine& e;
    RunObserver<Engine>* a;
    RunObserver<Engine>* b;
    ~Detach() {
      e.remove_observer(a);
      e.remove_observer(b);
    }
  } detach{engine, &output, &observer};
  double point_steps = 0.0;  // the point count may change (surface point management)
  auto statistics = [&] {
    RunStatistics r;
    r.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.particle_steps_per_second = r.wall_seconds > 0.0 ? point_steps / r.wall_seconds : 0.0;
    return r;
  };
  double next_checkpoint = control.checkpoint_interval > 0.0
                               ? engine.time() + control.checkpoint_interval
                               : std::numeric_limits<double>::infinity();
  int signal = 0;
  try {
    while (!engine.finished()) {
      if constexpr (requires { engine.settings().max_steps; }) {
        if (engine.step_count() >= engine.settings().max_steps)
          throw NumericalError({engine.time(), engine.step_count(), "", -1},
                               "solver.max_steps = " + std::to_string(engine.settings().max_steps) +
                                   " reached before end_time; the last time step was " +
                                   std::to_string(engine.last_dt()) +
                                   " (raise max_steps if that is meant)");
      }
      engine.step();
      point_steps += static_cast<double>(engine.point_count());
      signal = control.stop ? *control.stop : 0;
      if (control.ranks) signal = static_cast<int>(control.ranks->max(signal));
      if (signal) break;
      if (control.checkpoint && engine.time() + 1e-9 * engine.last_dt() >= next_checkpoint) {
        control.checkpoint();
        next_checkpoint = engine.time() + control.checkpoint_interval;
      }
    }
  } catch (const NumericalError& e) {
    if (progress) progress->finish(observer.report(engine));
    output.finish(engine, std::string("failed: ") + e.what(), control.case_hash,
                  statistics().wall_seconds);
    throw;
  }
  if (progress) progress->finish(observer.report(engine));
  RunStatistics r = statistics();
  r.interrupted_by = signal;
  // The state it ended in, to continue from.
  if (control.checkpoint && (signal || control.checkpoint_interval > 0.0)) control.checkpoint();
  output.finish(engine, signal ? "interrupted" : "completed", control.case_hash, r.wall_seconds);
  return r;
}

template RunStatistics run_simulation(Simulation<2>&, OutputWriter<2>&, ProgressListener*,
                                      const RunControl&);
template RunStatistics run_simulation(Simulation<3>&, OutputWriter<3>&, ProgressListener*,
                                      const RunControl&);
template RunStatistics run_simulation(SurfaceSimulation<2>&, SurfaceOutputWriter<2>&,
                                      ProgressListener*, const RunControl&);
template RunStatistics run_simulation(SurfaceSimulation<3>&, SurfaceOutputWriter<3>&,
                                      ProgressListener*, const RunControl&);

}  // namespace pellicle
