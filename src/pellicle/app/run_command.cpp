//! `pellicle run` and `pellicle check`.
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <optional>
#include <thread>

#include "pellicle/app/commands.hpp"
#include "pellicle/app/stop_signals.hpp"
#include "pellicle/app/terminal_progress.hpp"
#include "pellicle/core/error.hpp"
#include "pellicle/io/build.hpp"
#include "pellicle/io/case.hpp"
#include "pellicle/io/checkpoint.hpp"
#include "pellicle/io/output.hpp"
#include "pellicle/io/output_directory.hpp"
#include "pellicle/io/restart.hpp"
#include "pellicle/io/run.hpp"
#include "pellicle/io/surface_case.hpp"
#include "pellicle/io/vtk_writer.hpp"
#ifdef PELLICLE_WITH_MPI
#include "pellicle/dist/distributed_run.hpp"
#include "pellicle/dist/window_carrier.hpp"
#endif

namespace pellicle {

namespace {

int world_rank(const RunOptions& o) {
#ifdef PELLICLE_WITH_MPI
  if (o.world) return o.world->rank();
#endif
  return 0;
}

int world_size(const RunOptions& o) {
#ifdef PELLICLE_WITH_MPI
  if (o.world) return o.world->size();
#endif
  return 1;
}

const char* kinematics_name(Kinematics k) {
  switch (k) {
    case Kinematics::plane_strain:
      return "2D plane strain";
    case Kinematics::plane_stress:
      return "2D plane stress";
    case Kinematics::axisymmetric:
      return "2D axisymmetric (x = r, y = z)";
    case Kinematics::solid:
      return "3D";
  }
  return "";
}

//! Print the run's set-up to `out` (none: only the sums); returns the number of points. In a
//! distributed run every rank calls it, and the points, masses and memory are every rank's.
template <int D>
long print_summary(const Case<D>& c, const Simulation<D>& s, std::FILE* out) {
  const auto& p = s.points();
  std::vector<double> sums;  // per body its points and mass, then all points and the memory
  for (const auto& b : p.bodies) {
    double mass = 0.0;
    for (long i = b.begin; i < b.end; ++i) mass += p.mass[i];
    sums.push_back(static_cast<double>(b.count()));
    sums.push_back(mass);
  }
  sums.push_back(static_cast<double>(p.size()));
  sums.push_back(static_cast<double>(s.memory_estimate_bytes()));
  if (s.collective()) s.collective()->sum_in_rank_order(sums);
  const long points = std::lround(sums[sums.size() - 2]);
  const double memory = sums.back();
  const double dt = s.planned_dt();
  const double cfl = dt * s.max_wave_speed() / s.grid().cell();
  if (!out) return points;
  const auto& g = s.grid();
  long cells = 1;
  for (int d = 0; d < D; ++d) cells *= g.cells()[d];
  std::fprintf(out, "case      %s\n", c.title.c_str());
  if (!c.source.empty()) std::fprintf(out, "source    %s\n", c.source.c_str());
  std::fprintf(out, "model     %s, kernel %s\n", kinematics_name(c.settings.kinematics),
               c.kernel.c_str());
  std::fprintf(out, "grid      %ld cells (", cells);
  for (int d = 0; d < D; ++d) std::fprintf(out, "%s%d", d ? " x " : "", g.cells()[d]);
  long nodes = 1;  // of the whole grid (a distributed run's rank stores a window of it)
  for (int d = 0; d < D; ++d) nodes *= g.cells()[d] + 1 + 2 * Grid<D>::kGhost;
  std::fprintf(out, ") of %g m, %ld nodes with ghosts\n", g.cell(), nodes);
  // Plane runs carry mass per metre of depth; axisymmetric and 3D runs the whole body's.
  const char* mass_unit =
      D == 2 && c.settings.kinematics != Kinematics::axisymmetric ? "kg/m of depth" : "kg";
  for (std::size_t k = 0; k < p.bodies.size(); ++k) {
    const auto& b = p.bodies[k];
    std::fprintf(out, "body      %-16s %8ld points, mass %.6g %s, material '%s'\n", b.name.c_str(),
                 std::lround(sums[2 * k]), sums[2 * k + 1], mass_unit,
                 c.material_names[b.material].c_str());
  }
  for (const auto& b : c.bodies) {
    if (!b.membrane) continue;
    std::fprintf(out,
                 "membrane  %-16s spacing up to %.4g m (%.2g cells), thickness %g m, frames '%s'\n",
                 b.name.c_str(), b.membrane->longest_gap, b.membrane->longest_gap / g.cell(),
                 b.thickness, b.frames.c_str());
    if (b.membrane->longest_gap > g.cell())
      std::fprintf(out,
                   "warning   body '%s': neighbouring points are more than a cell apart; the "
                   "membrane would break (thesis §5.4.4): reduce its spacing\n",
                   b.name.c_str());
  }
  const bool flip =
      c.transfer.update == VelocityUpdate::flip || c.transfer.update == VelocityUpdate::blend;
  for (const auto& b : p.bodies) {
    const std::string caution = flip ? s.material(b.material).flip_caution() : "";
    if (!caution.empty())
      std::fprintf(out, "warning   body '%s' is %s\n", b.name.c_str(), caution.c_str());
  }
  std::fprintf(out, "contact   %s\n",
               s.contact() ? s.contact()->describe().c_str() : "single field (standard MPM)");
  std::fprintf(out, "points    %ld in all\n", points);
  std::fprintf(out, "time      end %g s, dt %.6g s (%s), CFL number %.3g, about %.0f steps\n",
               c.settings.end_time, dt, c.settings.fixed_dt > 0.0 ? "fixed" : "from cfl", cfl,
               std::ceil(c.settings.end_time / dt));
  std::fprintf(out, "memory    about %.1f MB (%.0f bytes a point, grid included)\n",
               memory / 1048576.0, memory / static_cast<double>(points));
  std::fprintf(out, "output    %s\n", c.output.directory.c_str());
  if (cfl > c.settings.cfl_limit)
    std::fprintf(out,
                 "warning   CFL number c dt / h above solver.cfl_limit = %g: the run will stop at "
                 "its first step\n",
                 c.settings.cfl_limit);
  return points;
}

//! A time step that cannot reach the end time within solver.max_steps (a body so fast or
//! stiff that the CFL step is nothing, or a dt far smaller than meant) is refused before
//! anything runs.
template <int D>
void refuse_endless_runs(const Case<D>& c, const Simulation<D>& s) {
  const double dt = s.planned_dt();
  const double steps = (c.settings.end_time - s.time()) / dt;
  const double allowed = static_cast<double>(c.settings.max_steps - s.step_count());
  if (dt > 0.0 && std::isfinite(dt) && steps <= allowed) return;
  char text[400];
  if (c.settings.fixed_dt > 0.0)
    std::snprintf(text, sizeof text,
                  "a time step of %.3g s takes %.3g steps to reach end_time = %g, more than "
                  "solver.max_steps = %ld",
                  dt, steps, c.settings.end_time, c.settings.max_steps);
  else
    std::snprintf(text, sizeof text,
                  "the CFL step is %.3g s (cell %g over the fastest signal, %.3g m/s) and takes "
                  "%.3g steps to reach end_time = %g, more than solver.max_steps = %ld: check "
                  "the bodies' velocities and stiffness",
                  dt, c.cell, s.max_signal_speed(), steps, c.settings.end_time,
                  c.settings.max_steps);
  throw InputError(c.time_step_where, c.time_step_key, text);
}

template <int D>
int run_case(const CaseSource& source, const RunOptions& o, bool check_only) {
  std::optional<CheckpointHeader> saved;
  if (!o.restart.empty()) {
    saved = read_checkpoint_header(o.restart);
    check_restart(*saved, o.restart, source);
  }
  Case<D> c = read_case<D>(source);
  if (!o.out_dir.empty()) c.output.directory = o.out_dir;
  if (o.checkpoint_interval > 0.0) c.output.checkpoint_interval = o.checkpoint_interval;
  const bool lead = world_rank(o) == 0, distributed = world_size(o) > 1 && !check_only;
  // A distributed run's ranks each build only the points of their patch (of the checkpoint's
  // positions when it continues one).
  PointSelection<D> select;
#ifdef PELLICLE_WITH_MPI
  std::vector<Patch<D>> patches;
  if (distributed) {
    if (saved) {  // rank 0 checks every piece once; each rank then opens only those it needs
      std::exception_ptr problem;
      if (lead) {
        try {
          check_checkpoint_pieces(o.restart);
        } catch (const InputError&) {
          problem = std::current_exception();
        }
      }
      if (o.world->max(problem ? 1.0 : 0.0) > 0.0) {
        if (problem) std::rethrow_exception(problem);
        throw InputError(SourceLocation{o.restart, 0, 0}, "--restart",
                         "a piece of the checkpoint is missing or foreign (rank 0 names it)");
      }
    }
    SavedPoints<D> points;
    if (saved)
      points = {[&o](const std::string& body) { return checkpoint_points(o.restart, body); },
                [&o](const std::string& body, const PartFilter<D>& read,
                     const std::function<void(long, const Vec<D>&)>& visit) {
                  for_each_saved_position<D>(o.restart, body, read, visit);
                }};
    select = patch_points<D>(*o.world, std::move(points), patches);
  }
#endif
  auto simulation = build_simulation<D>(c, std::move(select));
  if (saved) {
    PartFilter<D> read;  // a rank reads the pieces that can hold its points
#ifdef PELLICLE_WITH_MPI
    if (distributed) read = parts_near_patch(patches, simulation->grid(), world_rank(o));
#endif
    for (const auto& name : restore_checkpoint<D>(o.restart, *simulation, read))
      if (lead)
        std::fprintf(stderr, "restart   body '%s' is new: it starts from its case state\n",
                     name.c_str());
    if (simulation->finished())
      throw InputError(SourceLocation{c.file, 0, 0}, "solver.end_time",
                       "the checkpoint is at t = " + std::to_string(simulation->time()) +
                           ", not before the end time: raise solver.end_time to continue");
  }
#ifdef PELLICLE_WITH_MPI
  if (distributed) {
    try {
      distribute(*simulation, *o.world, std::move(patches));
    } catch (const SetupError& e) {
      throw InputError(SourceLocation{c.file, 0, 0}, "", e.what());
    }
  }
#endif
  refuse_endless_runs(c, *simulation);
  std::vector<Probe<D>> probes;
  for (const auto& spec : c.probes) probes.emplace_back(spec, *simulation);
  if (check_only) {
    print_summary(c, *simulation, stdout);
    std::printf("check     ok\n");
    return kExitOk;
  }
  // Collective in a distributed run: every rank adds its share.
  const long total_points = print_summary(c, *simulation, !o.quiet && lead ? stderr : nullptr);
  // Rank 0 claims the directory; the others learn whether it could.
  std::exception_ptr refused;
  if (lead) {
    try {
      claim_output_directory(c.output.directory, o.overwrite, SourceLocation{c.file, 0, 0},
                             o.out_dir.empty() ? "output.directory" : "--out");
    } catch (...) {
      refused = std::current_exception();
    }
  }
  if (distributed && simulation->collective()->max(refused ? 1.0 : 0.0) > 0.0 && !lead)
    return kExitBadInput;
  if (refused) std::rethrow_exception(refused);
  // From here a file that cannot be written (a full disk) is an output error (exit 1), not
  // a problem of the input.
  try {
    const auto writer = std::make_unique<OutputWriter<D>>(c.output, *simulation, std::move(probes));
    OutputWriter<D>& output = *writer;
    TerminalProgress progress(isatty(STDERR_FILENO));
    const CheckpointHeader header = checkpoint_header_for(source);
    const std::string checkpoint_path = c.output.directory + "/checkpoint.h5";
    RunControl control;
    control.case_hash = header.case_hash;
    control.checkpoint = [&] {
#ifdef PELLICLE_WITH_MPI
      if (distributed) {
        const WindowCarrier<D> to_whole_grid(simulation->grid(), *o.world);
        write_checkpoint(checkpoint_path, *simulation, header, &to_whole_grid);
        return;
      }
#endif
      write_checkpoint(checkpoint_path, *simulation, header);
    };
    control.checkpoint_interval = c.output.checkpoint_interval;
    control.stop = catch_stop_signals();
    control.ranks = simulation->collective();
    const RunStatistics r =
        run_simulation(*simulation, output, o.quiet || !lead ? nullptr : &progress, control);
    if (r.interrupted_by) {
      if (lead)
        std::fprintf(stderr,
                     "pellicle: interrupted (signal %d) at t=%g, step %ld; continue with "
                     "--restart %s\n",
                     r.interrupted_by, simulation->time(), simulation->step_count(),
                     checkpoint_path.c_str());
      return 128 + r.interrupted_by;
    }
    if (!lead) return kExitOk;
    if (!o.quiet)
      std::fprintf(stderr, "done      %ld steps in %.2f s, %.3g particle-steps/s on %d rank%s\n",
                   simulation->step_count(), r.wall_seconds,
                   r.wall_seconds > 0.0 ? static_cast<double>(total_points) *
                                              simulation->step_count() / r.wall_seconds
                                        : 0.0,
                   world_size(o), distributed ? "s" : "");
    std::printf("results   %s\n", output.directory().c_str());
    return kExitOk;
  } catch (const NumericalError& e) {
#ifdef PELLICLE_WITH_MPI
    if (distributed) {  // the other ranks wait in a collective call: stop them all
      std::fprintf(stderr, "pellicle: error on rank %d: %s\n", world_rank(o), e.what());
      // No summary (it needs every rank); the status file and the history rows so far stay.
      mark_output_directory(c.output.directory, std::string("failed: ") + e.what());
      std::fflush(stderr);
      o.world->abort(kExitNumericalFailure);
    }
#endif
    std::fprintf(stderr, "pellicle: error: %s\n", e.what());
    std::fprintf(stderr, "pellicle: the history and last snapshot up to the failure are in %s\n",
                 c.output.directory.c_str());
    return kExitNumericalFailure;
  } catch (const std::exception& e) {  // an output error: the run cannot go on
    mark_output_directory_failed(c.output.directory);
#ifdef PELLICLE_WITH_MPI
    if (distributed) {
      std::fprintf(stderr, "pellicle: error on rank %d: %s\n", world_rank(o), e.what());
      std::fflush(stderr);
      o.world->abort(1);  // an output error's exit code, as main gives it
    }
#endif
    throw;
  }
}

//! OpenMP threads of each rank: --threads, else OMP_NUM_THREADS, else the machine's cores
//! shared out among the ranks on it (all cores for every rank would make each rank's threads
//! wait for cores at every loop's end, many times slower).
void set_threads(const RunOptions& o) {
  if (o.threads > 0) {
    omp_set_num_threads(o.threads);
    return;
  }
#ifdef PELLICLE_WITH_MPI
  if (!o.world) return;
  // mpirun may bind a rank to fewer cores than the machine has (omp_get_num_procs).
  const int machine = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int ranks = o.world->ranks_on_this_machine();
  if (!std::getenv("OMP_NUM_THREADS"))
    omp_set_num_threads(std::max(1, std::min(omp_get_num_procs(), machine / ranks)));
  if (o.world->rank() == 0 && omp_get_max_threads() * ranks > machine)
    std::fprintf(stderr,
                 "pellicle: warning: %d ranks × %d threads on %d processors: more than the "
                 "processors, so they wait for each other; use fewer ranks or --threads\n",
                 ranks, omp_get_max_threads(), machine);
#endif
}

int run_or_check(const RunOptions& o, bool check_only) {
  set_threads(o);
  try {
    const auto source = load_case_source(o.case_path, o.overrides);
    if (is_surface_case(*source)) {
      if (!o.restart.empty() || o.checkpoint_interval > 0.0)
        throw InputError(SourceLocation{o.case_path, 0, 0}, "--restart",
                         "checkpoints and restarts are for MPM cases; surface cases run from "
                         "their start");
      return run_surface_case(*source, o, check_only);
    }
    return case_dimension(*source) == 2 ? run_case<2>(*source, o, check_only)
                                        : run_case<3>(*source, o, check_only);
  } catch (const InputError& e) {  // every rank finds the same problem; rank 0 reports it
    return world_rank(o) == 0 ? report_input_error(e) : kExitBadInput;
  } catch (const SetupError& e) {
    return world_rank(o) == 0 ? report_input_error(e) : kExitBadInput;
  }
}

}  // namespace

int report_input_error(const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  if (const auto* input = dynamic_cast<const InputError*>(&error)) {
    const std::size_t n = input->problems().size();
    std::fprintf(stderr, "pellicle: %zu problem%s in the input; nothing was run\n", n,
                 n == 1 ? "" : "s");
  }
  return kExitBadInput;
}

int command_run(const RunOptions& options) {
  return run_or_check(options, false);
}
int command_check(const RunOptions& options) {
  return run_or_check(options, true);
}

}  // namespace pellicle
