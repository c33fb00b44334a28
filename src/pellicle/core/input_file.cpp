#include "pellicle/core/input_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "pellicle/core/error.hpp"

namespace pellicle {

std::string read_input_file(const std::string& path, const std::string& key,
                            const std::string& what, std::uintmax_t largest) {
  namespace fs = std::filesystem;
  const SourceLocation where{path, 0, 0};
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status))
    throw InputError(where, key, "cannot open the " + what + ": no such file");
  if (fs::is_directory(status))
    throw InputError(where, key, "expected a " + what + ", found a directory");
  // A FIFO would block until written to, /dev/zero never ends.
  if (!fs::is_regular_file(status))
    throw InputError(where, key, "expected a " + what + ", found a pipe, socket or device");
  const std::uintmax_t size = fs::file_size(path, error);
  if (!error && size > largest)
    throw InputError(where, key,
                     "the " + what + " has " + std::to_string(size) + " bytes, more than the " +
                         std::to_string(largest) + " a " + what + " may have");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(where, key, "cannot open the " + what + " (no permission to read)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(where, key, "cannot read the " + what);
  return text.str();
}

}  // namespace pellicle
