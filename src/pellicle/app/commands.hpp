#pragma once
//! The subcommands of `pellicle`. Each returns the process exit code (see core/error.hpp).

#include <string>
#include <vector>

namespace pellicle {

class Communicator;

struct RunOptions {
  std::string case_path;  //!< empty: the built-in default case
  std::string out_dir;    //!< empty: the case's output.directory
  std::vector<std::string> overrides;
  bool quiet = false;
  int threads = 0;                  //!< 0: OpenMP default
  std::string restart;              //!< checkpoint to continue from; empty: start fresh
  double checkpoint_interval = -1;  //!< > 0 overrides output.checkpoint_interval
  bool overwrite = false;           //!< replace another run's files in the output directory
  //! The ranks when started by mpirun (builds with MPI), else null.
  const Communicator* world = nullptr;
};

int command_run(const RunOptions& options);
int command_check(const RunOptions& options);

struct CaseSource;
//! run/check of a case with a `[surface]` table (surface_run_command.cpp).
int run_surface_case(const CaseSource& source, const RunOptions& options, bool check_only);

struct BenchOptions {
  bool json = false;
  long points = 250000;
  long steps = 40;
  std::vector<int> threads;        //!< empty: 1 and 2
  std::vector<std::string> cases;  //!< benchmark names; empty: all
};

int command_bench(const BenchOptions& options);

struct ValidateOptions {
  bool full = false;
  std::vector<std::string> only;  //!< problem names; empty: all
  std::string out_dir;            //!< empty: results/validation
  bool update_docs = false;       //!< write into the source tree's docs/validation instead
};

//! `pellicle list cases|problems|estimators|kernels|materials`: what can be named;
//! `pellicle list keys [SECTION]`: the case-file keys the user guide documents (under SECTION).
int command_list(const std::string& what, const std::string& section);

//! Exit code 1 when a check is outside its accepted range.
int command_validate(const ValidateOptions& options);

struct NormalsOptions {
  std::string points;  //!< CSV: x,y[,z] and optionally the exact normal
  double cell = 0.0;
  std::string method = "isosurface-hybrid";
  std::vector<double> origin;  //!< a grid node; default the origin
  std::string out;
  std::string orient = "propagate";  //!< first signs: propagate or outward
  std::vector<double> inside;        //!< if given: every normal faces away from this point
};

int command_normals(const NormalsOptions& options);

//! Print an input problem list to stderr; returns kExitBadInput.
int report_input_error(const std::exception& error);

}  // namespace pellicle
