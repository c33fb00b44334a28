#pragma once
//! Starting a run from another run's checkpoint (`pellicle run CASE --restart FILE`). The
//! case may differ from the saved one only where a restart can honour it:
//!   solver.dt, solver.cfl, solver.cfl_limit, solver.end_time   the time stepping
//!   [output], [case], [[probe]], [contact], [[boundary]],      what is written, the contact
//!   grid.boundary                                              rule, boundary conditions
//!   [[body]] tables added or removed                           new bodies start from their
//!                                                              case state; removed ones go
//!   [[material]] tables added or removed                       (those no kept body uses)
//!   a kept [[body]]'s cut_at, external_force,                what acts on it from now on
//!   membrane.frames and membrane.orientation
//!   a kept [[material]]'s parameters (not its model)         e.g. a gas made inviscid
//! A body kept by name is otherwise unchanged (its state comes from the checkpoint), as is
//! every other key; anything else is refused with the key and its place in the new case.

#include <memory>
#include <string>

#include "pellicle/io/case.hpp"
#include "pellicle/io/checkpoint.hpp"

namespace pellicle {

//! The checkpoint header for a run of `source` (case text, TOML as run, hash).
CheckpointHeader checkpoint_header_for(const CaseSource& source);

//! Refuse (InputError, every problem listed) a restart of `now` from a checkpoint written
//! by another Pellicle version, in another dimension, or whose case differs from `now` in a
//! key a restart cannot change.
void check_restart(const CheckpointHeader& saved, const std::string& checkpoint_path,
                   const CaseSource& now);

}  // namespace pellicle
