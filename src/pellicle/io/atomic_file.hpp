#pragma once
//! Whole-file writes that never leave a truncated file behind: the content goes to a
//! temporary name in the same directory, which is renamed over the target when complete.

#include <string>
#include <string_view>

namespace pellicle {

//! Throws std::runtime_error naming the file when it cannot be written.
void write_file_atomically(const std::string& path, std::string_view content);

}  // namespace pellicle
