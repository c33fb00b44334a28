#include "pellicle/io/run.hpp"

#include <chrono>
#include <limits>

#include "pellicle/core/error.hpp"
#include "pellicle/io/progress_observer.hpp"

namespace pellicle {

template <int D>
RunStatistics run_simulation(Simulation<D>& simulation, OutputWriter<D>& output,
                             ProgressListener* progress, const RunControl& control) {
  const std::string& case_hash = control.header.case_hash;
  const auto start = std::chrono::steady_clock::now();
  ProgressObserver<Simulation<D>, StepObserver<D>> observer(progress, start);
  simulation.add_observer(&output);
  simulation.add_observer(&observer);
  struct Detach {  // the observers live only as long as this call
    Simulation<D>& s;
    StepObserver<D>* a;
    StepObserver<D>* b;
    ~Detach() {
      s.remove_observer(a);
      s.remove_observer(b);
    }
  } detach{simulation, &output, &observer};
  const long first_step = simulation.step_count();
  auto statistics = [&] {
    RunStatistics r;
    r.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double point_steps =
        static_cast<double>(simulation.points().size()) * (simulation.step_count() - first_step);
    r.particle_steps_per_second = r.wall_seconds > 0.0 ? point_steps / r.wall_seconds : 0.0;
    return r;
  };
  double next_checkpoint = control.checkpoint_interval > 0.0
                               ? simulation.time() + control.checkpoint_interval
                               : std::numeric_limits<double>::infinity();
  auto checkpoint = [&] {
    if (!control.checkpoint_path.empty())
      write_checkpoint(control.checkpoint_path, simulation, control.header);
  };
  int signal = 0;
  try {
    while (!simulation.finished()) {
      simulation.step();
      if (control.stop && *control.stop) {
        signal = *control.stop;
        break;
      }
      if (simulation.time() + 1e-9 * simulation.last_dt() >= next_checkpoint) {
        checkpoint();
        next_checkpoint = simulation.time() + control.checkpoint_interval;
      }
    }
  } catch (const NumericalError& e) {
    if (progress) progress->finish(observer.report(simulation));
    output.finish(simulation, std::string("failed: ") + e.what(), case_hash,
                  statistics().wall_seconds);
    throw;
  }
  if (progress) progress->finish(observer.report(simulation));
  RunStatistics r = statistics();
  r.interrupted_by = signal;
  if (signal || control.checkpoint_interval > 0.0) checkpoint();  // the state it ended in
  output.finish(simulation, signal ? "interrupted" : "completed", case_hash, r.wall_seconds);
  return r;
}

template RunStatistics run_simulation<2>(Simulation<2>&, OutputWriter<2>&, ProgressListener*,
                                         const RunControl&);
template RunStatistics run_simulation<3>(Simulation<3>&, OutputWriter<3>&, ProgressListener*,
                                         const RunControl&);

}  // namespace pellicle
