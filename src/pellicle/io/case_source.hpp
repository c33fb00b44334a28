#pragma once
//! The parsed text of a case file, shared by the readers of MPM and surface cases (io/ only:
//! it carries toml++).

#include <string>

#include <toml++/toml.h>

#include "pellicle/core/error.hpp"
#include "pellicle/io/case.hpp"

namespace pellicle {

struct CaseSource {
  std::string file;  //!< path as given, or "<default case>"
  std::string text;
  toml::table root;
};

//! file:line:col of a node.
SourceLocation location_of(const toml::source_region& src, const std::string& file);

class TomlParameters;
//! The keys every case's `[output]` shares: directory, history_interval and
//! snapshot_interval (defaults from the case name and end time).
OutputSettings read_output_settings(TomlParameters& output, const std::string& name,
                                    double end_time);

}  // namespace pellicle
