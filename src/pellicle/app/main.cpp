//! The `pellicle` command line.
#include <omp.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "pellicle/app/commands.hpp"
#include "pellicle/core/error.hpp"
#include "pellicle/core/log.hpp"
#ifdef PELLICLE_WITH_MPI
#include "pellicle/dist/communicator.hpp"
#endif

namespace {

//! A thread count: a whole number from 1 to the machine's processors (more only slows a run:
//! the threads wait for each other at every loop's end).
CLI::Validator thread_count() {
  const int processors = omp_get_num_procs();
  return CLI::Validator(
      [processors](std::string& text) -> std::string {
        std::size_t used = 0;
        long value = 0;
        try {
          value = std::stol(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used != text.size() || value < 1 || value > processors)
          return "expected a whole number from 1 to " + std::to_string(processors) +
                 " (this machine's processors), found '" + text + "'";
        return "";
      },
      "INT in [1, " + std::to_string(processors) + "]");
}

//! Ranks mpirun (OpenMPI) or another launcher (PMI) started this process among; 0: none.
int launched_ranks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(name)) return std::atoi(value);
  return std::getenv("PMIX_RANK") ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace pellicle;
  set_log_sink([](LogLevel level, std::string_view message) {
    const char* tag = level == LogLevel::warning ? "warning: "
                      : level == LogLevel::error ? "error: "
                                                 : "";
    std::fprintf(stderr, "pellicle: %s%.*s\n", tag, static_cast<int>(message.size()),
                 message.data());
  });

  CLI::App app{"Pellicle: MPM for membranes, gases and solids"};
  app.set_version_flag("--version", std::string("pellicle ") + PELLICLE_VERSION + " (commit " +
                                        PELLICLE_COMMIT + ", " + PELLICLE_BUILD_TYPE + " build, " +
                                        PELLICLE_INSTRUCTION_SET + ")");
  app.require_subcommand(1);

  RunOptions run;
  auto* run_cmd = app.add_subcommand("run", "Run a case (the built-in airbag demo without CASE)");
  run_cmd->add_option("case", run.case_path, "Case file (TOML)");
  run_cmd->add_option("--out", run.out_dir, "Output directory (overrides output.directory)");
  run_cmd->add_option("--set", run.overrides, "Override a case key: --set solver.end_time=0.5")
      ->allow_extra_args(false);
  run_cmd->add_flag("--quiet,-q", run.quiet, "No summary or progress, only errors");
  run_cmd->add_flag("--overwrite", run.overwrite,
                    "Replace another run's results in the output directory (only Pellicle's "
                    "files are removed)");
  run_cmd
      ->add_option("--threads", run.threads,
                   "OpenMP threads (default: all cores, shared out among mpirun's ranks)")
      ->check(thread_count());
  run_cmd->add_option("--restart", run.restart,
                      "Continue from a checkpoint (the case may change restart-safe keys)");
  run_cmd
      ->add_option("--checkpoint-interval", run.checkpoint_interval,
                   "Simulated time between checkpoints (overrides output.checkpoint_interval)")
      ->check(CLI::PositiveNumber);

  RunOptions check;
  auto* check_cmd =
      app.add_subcommand("check", "Validate a case and print its summary without running");
  check_cmd->add_option("case", check.case_path, "Case file (TOML)")->required();
  check_cmd->add_option("--set", check.overrides, "Override a case key")->allow_extra_args(false);

  BenchOptions bench;
  auto* bench_cmd = app.add_subcommand(
      "bench", "Throughput and bytes per point of the MPM step, 1 and 2 threads");
  bench_cmd->add_flag("--json", bench.json, "Print a JSON list instead of text");
  bench_cmd->add_option("--points", bench.points, "Approximate number of points")
      ->check(CLI::Range(1000L, 100000000L));
  bench_cmd->add_option("--steps", bench.steps, "Timed steps")->check(CLI::Range(1L, 100000L));
  bench_cmd->add_option("--threads", bench.threads, "Thread counts to measure (default: 1 2)")
      ->check(thread_count());
  bench_cmd->add_option("--case", bench.cases, "Run only these benchmarks (default: all)")
      ->allow_extra_args(false);

  ValidateOptions validate;
  auto* validate_cmd = app.add_subcommand(
      "validate", "Run the validation problems against their references; write a report and plots");
  validate_cmd->add_flag("--full", validate.full, "Full resolution (the seeds' grids)");
  validate_cmd->add_flag("--update-docs", validate.update_docs,
                         "Write the report and plots into the source tree's docs/validation");
  validate_cmd->add_option("--only", validate.only, "Run only these problems")
      ->allow_extra_args(false);
  validate_cmd->add_option("--out", validate.out_dir, "Output directory");

  NormalsOptions normals;
  auto* normals_cmd = app.add_subcommand(
      "normals", "Normals of points from a CSV file by a connectivity-free estimator");
  normals_cmd
      ->add_option("--points", normals.points, "CSV of x,y[,z] with optional exact normal columns")
      ->required();
  normals_cmd->add_option("--cell", normals.cell, "Grid cell size")
      ->required()
      ->check(CLI::PositiveNumber);
  normals_cmd->add_option("--method", normals.method, "Estimator (default isosurface-hybrid)");
  normals_cmd->add_option("--origin", normals.origin, "A grid node, X,Y[,Z] (default 0)")
      ->delimiter(',');
  normals_cmd->add_option("--out", normals.out, "Output CSV")->required();
  normals_cmd
      ->add_option("--orient", normals.orient,
                   "Signs: propagate (neighbours agree) or outward (away from the centroid)")
      ->check(CLI::IsMember({"propagate", "outward"}));
  normals_cmd
      ->add_option("--inside", normals.inside,
                   "Orient every normal away from this point, X,Y[,Z] (overrides --orient)")
      ->delimiter(',');

  std::string list_what, list_section;
  auto* list_cmd = app.add_subcommand(
      "list", "List what a case or command can name, or the keys a case file can hold");
  list_cmd->add_option("what", list_what, "cases, problems, estimators, kernels, materials or keys")
      ->required()
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            for (const char* word :
                 {"cases", "problems", "estimators", "kernels", "materials", "keys"})
              if (text == word) return "";
            return "expected cases, problems, estimators, kernels, materials or keys, found '" +
                   text + "'";
          },
          "WORD"));
  list_cmd->add_option("section", list_section,
                       "With keys: only this section's, e.g. solver or body.membrane");
  auto* help_cmd = app.add_subcommand("help", "Print this help");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }

#ifdef PELLICLE_WITH_MPI
  // A run started by mpirun is distributed over its ranks (MPI lives until main returns).
  std::optional<Communicator> world;
  if (*run_cmd && launched_ranks() > 0) {
    world.emplace(argc, argv);
    run.world = &*world;
  }
#else
  if (*run_cmd && launched_ranks() > 1) {
    std::fprintf(stderr,
                 "pellicle: error: started on %d ranks, but this build has no MPI (configure "
                 "with PELLICLE_MPI=ON and OpenMPI installed: scripts/setup installs it)\n",
                 launched_ranks());
    return kExitBadInput;
  }
#endif
  try {
    if (*run_cmd) return command_run(run);
    if (*check_cmd) return command_check(check);
    if (*bench_cmd) return command_bench(bench);
    if (*validate_cmd) return command_validate(validate);
    if (*normals_cmd) return command_normals(normals);
    if (*list_cmd) return command_list(list_what, list_section);
    if (*help_cmd) {
      // app.help() would describe the `help` subcommand just parsed; the formatter gives the
      // program's own.
      std::printf(
          "%s",
          app.get_formatter()->make_help(&app, "pellicle", CLI::AppFormatMode::Normal).c_str());
      return kExitOk;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pellicle: error: %s\n", e.what());
    return 1;
  }
  return kExitOk;
}
