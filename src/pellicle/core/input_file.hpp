#pragma once
//! Reading an input file whole (a case, a point table, a mesh) with the checks that keep a
//! wrong path from blocking or exhausting memory: only regular files, of bounded size.

#include <cstdint>
#include <string>

namespace pellicle {

//! The contents of `path`. Throws InputError naming `path` and `key` (the option or case key
//! that gave the path; may be empty) when the file does not exist, cannot be read, is a
//! directory, a pipe, a socket or a device, or is larger than `largest` bytes; `what` names
//! the kind of file in the messages ("case file", "STL file").
std::string read_input_file(const std::string& path, const std::string& key,
                            const std::string& what, std::uintmax_t largest);

}  // namespace pellicle
