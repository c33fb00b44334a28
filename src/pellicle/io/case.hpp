#pragma once
//! A case file read, checked and typed: everything needed to build a Simulation, with no
//! TOML left in it. Every key is documented in docs/user-guide.md.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pellicle/core/error.hpp"
#include "pellicle/core/types.hpp"
#include "pellicle/geometry/membrane_geometry.hpp"
#include "pellicle/geometry/region.hpp"
#include "pellicle/io/probes.hpp"
#include "pellicle/mpm/builder.hpp"
#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/materials/material.hpp"
#include "pellicle/mpm/simulation.hpp"
#include "pellicle/mpm/transfer.hpp"
#include "pellicle/normals/frame_estimator.hpp"

namespace pellicle {

struct OutputSettings {
  std::string directory;           //!< where results go (created)
  double history_interval = 0.0;   //!< simulated time between history rows; 0: every step
  double snapshot_interval = 0.0;  //!< simulated time between snapshots; 0: first and last only
  bool grid_snapshots = false;     //!< also write .vti grid snapshots
  //! Simulated time between checkpoints (checkpoint.h5); 0: only when interrupted.
  double checkpoint_interval = 0.0;
};

//! A body as the case describes it: the builder's set-up and where its table is.
template <int D>
struct BodySpec : BodySetup<D> {
  SourceLocation where;  //!< the body's table, for problems found when filling it
};

template <int D>
struct Case {
  std::string file, name, title, source;
  Vec<D> lower, upper;
  double cell = 0.0;
  FaceConditions<D> faces{};
  SimulationSettings settings;
  TransferOptions transfer;
  std::string kernel = "linear";
  Vec<D> gravity = Vec<D>::Zero();
  OutputSettings output;
  std::vector<std::string> material_names;
  std::vector<std::unique_ptr<Material<D>>> materials;
  std::vector<BodySpec<D>> bodies;
  std::unique_ptr<ContactModel<D>> contact;              //!< null: the single centre-of-mass field
  std::vector<std::unique_ptr<StepHook<D>>> boundaries;  //!< [[boundary]] conditions
  std::vector<ProbeSpec<D>> probes;
  SourceLocation cell_where;  //!< grid.cell in the input
  //! The key that sets the time step (solver.dt, or solver.cfl given or not) and where.
  std::string time_step_key;
  SourceLocation time_step_where;
};

//! A parsed case file whose dimension is known, before typing (see read_case).
struct CaseSource;

//! Parse a case file (or the built-in default when `path` is empty) and apply `--set`
//! overrides ("key.path=value"). Throws InputError (exit 2) on any problem.
std::shared_ptr<CaseSource> load_case_source(const std::string& path,
                                             const std::vector<std::string>& overrides);
//! The same from case text already in memory; `name` stands for the file in messages.
std::shared_ptr<CaseSource> case_source_from_text(const std::string& text, const std::string& name,
                                                  const std::vector<std::string>& overrides = {});
//! 2 or 3, from the length of grid.lower.
int case_dimension(const CaseSource& source);
//! Type and check every key. Throws InputError listing every problem found.
template <int D>
Case<D> read_case(const CaseSource& source);
//! The case text (for hashing into summary.json).
const std::string& case_text(const CaseSource& source);

//! The built-in default case: the airbag demo (cases/airbag_demo.toml).
const std::string& default_case_text();

}  // namespace pellicle
