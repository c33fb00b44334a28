#include "pellicle/io/surface_run.hpp"

#include <chrono>

#include "pellicle/core/error.hpp"
#include "pellicle/io/progress_observer.hpp"

namespace pellicle {

template <int D>
RunStatistics run_surface_simulation(SurfaceSimulation<D>& simulation,
                                     SurfaceOutputWriter<D>& output, ProgressListener* progress,
                                     const std::string& case_hash) {
  const auto start = std::chrono::steady_clock::now();
  ProgressObserver<SurfaceSimulation<D>, SurfaceObserver<D>> observer(progress, start);
  simulation.add_observer(&output);
  simulation.add_observer(&observer);
  double point_steps = 0.0;
  struct Count final : SurfaceObserver<D> {
    double& total;
    explicit Count(double& t) : total(t) {}
    void after_step(const SurfaceSimulation<D>& s) override { total += s.cloud().size(); }
  } count(point_steps);
  simulation.add_observer(&count);
  struct Detach {  // the observers live only as long as this call
    SurfaceSimulation<D>& s;
    std::vector<SurfaceObserver<D>*> observers;
    ~Detach() {
      for (auto* o : observers) s.remove_observer(o);
    }
  } detach{simulation, {&output, &observer, &count}};
  const auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  try {
    simulation.run();
  } catch (const NumericalError& e) {
    if (progress) progress->finish(observer.report(simulation));
    output.finish(simulation, std::string("failed: ") + e.what(), case_hash, seconds());
    throw;
  }
  if (progress) progress->finish(observer.report(simulation));
  RunStatistics r;
  r.wall_seconds = seconds();
  r.particle_steps_per_second = r.wall_seconds > 0.0 ? point_steps / r.wall_seconds : 0.0;
  output.finish(simulation, "completed", case_hash, r.wall_seconds);
  return r;
}

template RunStatistics run_surface_simulation<2>(SurfaceSimulation<2>&, SurfaceOutputWriter<2>&,
                                                 ProgressListener*, const std::string&);
template RunStatistics run_surface_simulation<3>(SurfaceSimulation<3>&, SurfaceOutputWriter<3>&,
                                                 ProgressListener*, const std::string&);

}  // namespace pellicle
