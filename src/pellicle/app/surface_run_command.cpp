//! `pellicle run` and `pellicle check` for surface cases (a `[surface]` table).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pellicle/app/commands.hpp"
#include "pellicle/app/stop_signals.hpp"
#include "pellicle/app/terminal_progress.hpp"
#include "pellicle/core/error.hpp"
#include "pellicle/io/output.hpp"
#include "pellicle/io/output_directory.hpp"
#include "pellicle/io/problem_size.hpp"
#include "pellicle/io/run.hpp"
#include "pellicle/io/surface_case.hpp"
#include "pellicle/io/surface_output.hpp"

namespace pellicle {

namespace {

template <int D>
void print_surface_summary(const SurfaceCase<D>& c, const SurfaceSimulation<D>& s, std::FILE* out) {
  const auto& cloud = s.cloud();
  const auto& nb = s.neighbours();
  long boundary = 0;
  int fewest = 1 << 30, most = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    boundary += cloud.boundary[i];
    fewest = std::min(fewest, nb.count(i) - 1);
    most = std::max(most, nb.count(i) - 1);
  }
  const double mean = static_cast<double>(nb.index.size()) / cloud.size() - 1.0;
  std::fprintf(out, "case       %s\n", c.title.c_str());
  if (!c.source.empty()) std::fprintf(out, "source     %s\n", c.source.c_str());
  for (const auto& surface : c.surfaces)
    std::fprintf(out, "surface    %s%s%s (%s)\n", c.surfaces.size() > 1 ? surface.name.c_str() : "",
                 c.surfaces.size() > 1 ? ": " : "", surface.shape->describe().c_str(),
                 D == 2 ? "curve in 2D" : "surface in 3D");
  const ContactOptions& contact = c.settings.contact;
  const auto& names = contact_response_names();
  if (c.surfaces.size() > 1 || contact.self_contact())
    std::fprintf(out, "contact    between surfaces %s, within a surface %s, %zu rule(s) (§3.6)\n",
                 names[static_cast<int>(contact.between)].c_str(),
                 names[static_cast<int>(contact.self)].c_str(), contact.rules.size());
  std::fprintf(out, "points     %zu (%ld on the boundary), h %g, spacing %g (%.3g h)\n",
               cloud.size(), boundary, c.smoothing_length, c.spacing,
               c.spacing / c.smoothing_length);
  std::fprintf(out, "neighbours %.1f per point within h (fewest %d, most %d)\n", mean, fewest,
               most);
  std::string velocity;
  for (int d = 0; d < D; ++d) velocity += (d ? ", " : "") + c.velocity[d].text();
  std::fprintf(
      out, "movement   %s, velocity (%s)\n",
      c.settings.movement == MovementOrder::second ? "second order (eq 3)" : "first order (eq 2)",
      velocity.c_str());
  if (c.settings.manage)
    std::fprintf(
        out, "management r_max %g, r_min %g, %s addition\n", c.settings.management.r_max,
        c.settings.management.r_min,
        c.settings.management.curvature_correction ? "curvature-corrected" : "circumcentre");
  else
    std::fprintf(out, "management off\n");
  std::fprintf(out, "pde        %s\n",
               s.pde() ? s.pde()->describe().c_str() : "none (movement only)");
  std::fprintf(out, "time       end %g, dt %g, about %.0f steps\n", c.settings.end_time,
               c.settings.dt, std::ceil(c.settings.end_time / c.settings.dt - 1e-9));
  // As for MPM cases: what the run will hold, and what the case alone gave before sampling
  // (the check that refuses clouds too large for the machine).
  const SurfaceSize estimate = estimate_surface_size<D>(c.shapes(), c.spacing);
  std::fprintf(out,
               "memory     about %.1f MB (%.1f kB a point; the shape's %s gave %.0f points "
               "before sampling)\n",
               cloud.size() * surface_bytes_per_point<D>() / 1048576.0,
               surface_bytes_per_point<D>() / 1024.0, D == 2 ? "length" : "area", estimate.points);
  std::fprintf(out, "output     %s\n", c.output.directory.c_str());
  if (fewest < 8)
    std::fprintf(out,
                 "warning    some points have fewer than 8 neighbours within h; second-order "
                 "stencils need 6 well spread: raise h or refine the cloud\n");
}

template <int D>
int run_surface(const CaseSource& source, const RunOptions& o, bool check_only) {
  SurfaceCase<D> c = read_surface_case<D>(source);
  if (!o.out_dir.empty()) c.output.directory = o.out_dir;
  std::unique_ptr<SurfaceSimulation<D>> simulation;
  try {
    simulation = build_surface_simulation<D>(c);
  } catch (const NumericalError& e) {  // the initial cloud cannot carry the operators
    std::fprintf(stderr, "pellicle: error: the initial cloud: %s\n", e.what());
    return kExitNumericalFailure;
  }
  if (check_only) {
    print_surface_summary(c, *simulation, stdout);
    std::printf("check      ok\n");
    return kExitOk;
  }
  if (!o.quiet) print_surface_summary(c, *simulation, stderr);
  claim_output_directory(c.output.directory, o.overwrite, SourceLocation{c.file, 0, 0},
                         o.out_dir.empty() ? "output.directory" : "--out");
  // From here a file that cannot be written (a full disk) is an output error (exit 1), not
  // a problem of the input.
  try {
    const auto writer = std::make_unique<SurfaceOutputWriter<D>>(c.output, *simulation, c.monitors);
    TerminalProgress progress(isatty(STDERR_FILENO));
    RunControl control;
    control.case_hash = hash_text(case_text(source));
    control.stop = catch_stop_signals();
    const RunStatistics r =
        run_simulation(*simulation, *writer, o.quiet ? nullptr : &progress, control);
    if (r.interrupted_by) {
      std::fprintf(stderr, "pellicle: interrupted (signal %d) at t=%g, step %ld\n",
                   r.interrupted_by, simulation->time(), simulation->step_count());
      return 128 + r.interrupted_by;
    }
    if (!o.quiet)
      std::fprintf(stderr, "done       %ld steps in %.2f s, %.3g point-steps/s, %zu points\n",
                   simulation->step_count(), r.wall_seconds, r.particle_steps_per_second,
                   simulation->cloud().size());
    std::printf("results   %s\n", writer->directory().c_str());
    return kExitOk;
  } catch (const NumericalError& e) {
    std::fprintf(stderr, "pellicle: error: %s\n", e.what());
    std::fprintf(stderr, "pellicle: the history and last snapshot up to the failure are in %s\n",
                 c.output.directory.c_str());
    return kExitNumericalFailure;
  } catch (const std::exception&) {  // an output error: the run cannot go on
    mark_output_directory_failed(c.output.directory);
    throw;
  }
}

}  // namespace

int run_surface_case(const CaseSource& source, const RunOptions& options, bool check_only) {
  return surface_case_dimension(source) == 2 ? run_surface<2>(source, options, check_only)
                                             : run_surface<3>(source, options, check_only);
}

}  // namespace pellicle
