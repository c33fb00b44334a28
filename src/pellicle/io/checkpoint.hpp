#pragma once
//! Checkpoints: the whole state of an MPM run in one HDF5 file, written atomically (a
//! temporary name, then rename), readable with h5py or h5dump. Layout:
//!   /                 attributes format, version, dimension, case_file, case_hash,
//!                     case_text (as given), case_toml (with --set applied), time, step,
//!                     last_dt, max_speed, rng
//!   /bodies/body_N    attributes name, material; datasets position, velocity, mass,
//!                     volume, density, stress, and columns/<name> for every declared
//!                     column marked for checkpoints (one row per point)
//!   /hooks/<name>     the arrays of hooks that carry state (contact-release's node states)
//! A distributed run's checkpoint is this file without the bodies' point datasets (each body
//! group has attribute `points`, its point count as built, and dataset `boxes`, the lower and
//! upper corners of the box around each piece's points of the body; the file attribute
//! `pieces` is the number of ranks), beside one piece per rank, checkpoint_rNNNN.h5
//! (attributes format, step, rank): /bodies/body_N with the rank's points of the body, their
//! datasets as above and `body_index`, each point's index in its body as built.
//! The frame estimators draw their random points from a generator seeded per cell, so the
//! run has no random state beyond the seed recorded in `rng`.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pellicle/dist/decomposition.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

//! What identifies a checkpoint and the run it belongs to.
struct CheckpointHeader {
  std::string version;  //!< Pellicle version that wrote it
  int dimension = 0;
  std::string case_file;  //!< the case file's name as given
  std::string case_hash;  //!< hash of the case text with its --set overrides
  std::string case_text;  //!< the case as given, overrides appended as comments
  std::string case_toml;  //!< the case as run (overrides applied), TOML
  double time = 0.0;
  long step = 0;
};

//! Write the state of `simulation` to `path` (atomically). Throws std::runtime_error naming
//! the path when it cannot be written. A distributed run's ranks all call it: each writes its
//! piece, then rank 0 the file at `path`, with the hooks' node states brought to the whole
//! grid by `to_whole_grid`. Any number of ranks, one included, can continue from it.
template <int D>
void write_checkpoint(const std::string& path, const Simulation<D>& simulation,
                      const CheckpointHeader& header, const NodeCarrier* to_whole_grid = nullptr);

//! Read the header. Throws InputError naming the file when it is not a Pellicle checkpoint.
CheckpointHeader read_checkpoint_header(const std::string& path);

//! Check that each piece of a distributed run's checkpoint is there and is a piece of it (one
//! opening per piece); nothing to check for a checkpoint of one file. Throws InputError naming
//! the first piece that is not. A continued run's ranks open only the pieces they need.
void check_checkpoint_pieces(const std::string& path);

//! Continue `simulation` (built from the case, possibly changed) from the checkpoint: every
//! body found in it by name takes its saved points (the point count must match; a body built
//! in part, as a distributed run's rank builds it, takes the rows of its points' indices in the
//! body, column_names::body_index), the clock and the hooks' state are restored. Returns the names
//! of bodies the checkpoint does not hold (added by the changed case; they start from their case
//! state). Throws InputError for a body whose point count changed or a declared column the
//! checkpoint lacks. `read`: the parts that can hold this process's points (a rank of a
//! distributed run: the pieces whose boxes meet its patch); std::logic_error when a point of
//! the process is in none of them.
template <int D>
std::vector<std::string> restore_checkpoint(const std::string& path, Simulation<D>& simulation,
                                            const PartFilter<D>& read = {});

//! The number of points the checkpoint holds of the body of this name; none when it holds no
//! such body. Throws InputError naming the file when it cannot be read.
std::optional<long> checkpoint_points(const std::string& path, const std::string& body);

//! visit(index in the body as built, position) for each point the checkpoint holds of the
//! body of this name in the parts `read` accepts (nothing when it holds no such body). Throws
//! InputError naming the file when it cannot be read.
template <int D>
void for_each_saved_position(const std::string& path, const std::string& body,
                             const PartFilter<D>& read,
                             const std::function<void(long, const Vec<D>&)>& visit);

}  // namespace pellicle
