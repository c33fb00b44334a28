#pragma once
//! A run owns its output directory: it never mixes its files with another run's, and the
//! directory says at every moment whether its run is running, completed, failed or
//! interrupted (the file `status`, one word).

#include <string>

#include "pellicle/core/error.hpp"

namespace pellicle {

//! Make `directory` this run's. Created if missing; a directory that holds anything is
//! refused (InputError at `where`, key `key`) unless `overwrite`, which removes Pellicle's
//! own files there (history, summary, status, snapshots and their series, the checkpoint,
//! the plots) and leaves every other file. Then marks it running. A directory that cannot
//! be created for want of room (or a failing device), and a status file that cannot be
//! written, are output errors (std::runtime_error naming the path), not the input's.
void claim_output_directory(const std::string& directory, bool overwrite,
                            const SourceLocation& where, const std::string& key);

//! Replace the status file with the first word of `status` ("completed", "failed: …",
//! "interrupted").
void mark_output_directory(const std::string& directory, const std::string& status);

//! Mark the directory failed after an output error, if the disk still lets us (never throws).
void mark_output_directory_failed(const std::string& directory) noexcept;

}  // namespace pellicle
