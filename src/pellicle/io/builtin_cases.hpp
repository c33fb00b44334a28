#pragma once
//! The case files of cases/, compiled in: the default case and the validation problems run
//! from the binary alone.

#include <string>
#include <utility>
#include <vector>

namespace pellicle {

//! (file name, text) of every case under cases/ at build time.
const std::vector<std::pair<std::string, std::string>>& builtin_cases();
//! Text of a built-in case by file name ("two_disks.toml"); throws InputError if unknown.
const std::string& builtin_case(const std::string& file_name);

}  // namespace pellicle
