#include "pellicle/io/output_directory.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "pellicle/io/atomic_file.hpp"

namespace pellicle {

namespace {

namespace fs = std::filesystem;

//! Files a run (or the plotting tools run on its results) writes; checkpoint_rNNNN.h5 are the
//! ranks' pieces of a distributed run's checkpoint.
bool written_by_pellicle(const fs::path& file) {
  static const std::set<std::string> names = {"history.csv", "summary.json", "status",
                                              "checkpoint.h5"};
  static const std::set<std::string> extensions = {".vtu",  ".vti", ".vtp", ".pvtu",
                                                   ".pvti", ".pvd", ".png", ".part"};
  const std::string name = file.filename().string();
  const bool piece = name.starts_with("checkpoint_r") && file.extension() == ".h5";
  return piece || names.count(name) || extensions.count(file.extension().string());
}

//! The file system is full or failing, whatever the path (ENOSPC, EDQUOT, EIO).
bool device_failure(const std::error_code& ec) {
  const std::error_condition c = ec.default_error_condition();
  return c == std::errc::no_space_on_device || c == std::errc::io_error ||
         c == std::error_condition(EDQUOT, std::generic_category());
}

//! The word in the status file a run left, or "" when there is none.
std::string previous_status(const fs::path& directory) {
  std::ifstream in(directory / "status");
  std::string word;
  in >> word;
  return word;
}

}  // namespace

void claim_output_directory(const std::string& directory, bool overwrite,
                            const SourceLocation& where, const std::string& key) {
  std::error_code ec;
  if (fs::exists(directory, ec) && !fs::is_directory(directory, ec))
    throw InputError(where, key, "cannot create " + directory + ": a file of that name exists");
  if (fs::is_directory(directory, ec)) {
    std::vector<fs::path> ours;
    long others = 0;
    for (const auto& entry : fs::directory_iterator(directory, ec)) {
      if (entry.is_regular_file(ec) && written_by_pellicle(entry.path()))
        ours.push_back(entry.path());
      else
        ++others;
    }
    if (!overwrite && (!ours.empty() || others > 0)) {
      const std::string status = previous_status(directory);
      throw InputError(
          where, key,
          directory + " is not empty" +
              (ours.empty() ? std::string(" (it holds no run's results)")
                            : " (another run's results" +
                                  (status.empty() ? std::string() : ", " + status) + ")") +
              ": give another --out, or --overwrite to replace Pellicle's files there");
    }
    for (const auto& file : ours) {
      fs::remove(file, ec);
      if (ec) throw InputError(where, key, "cannot remove " + file.string() + ": " + ec.message());
    }
  } else {
    fs::create_directories(directory, ec);
    // A path that cannot be a directory (a file in the way, no permission) is the input's
    // fault; a device that has no room or fails is not: an output error (exit 1).
    if (ec && device_failure(ec))
      throw std::runtime_error("cannot create " + directory + ": " + ec.message());
    if (ec) throw InputError(where, key, "cannot create " + directory + ": " + ec.message());
  }
  mark_output_directory(directory, "running");
}

void mark_output_directory(const std::string& directory, const std::string& status) {
  write_file_atomically(directory + "/status", status.substr(0, status.find(':')) + "\n");
}

void mark_output_directory_failed(const std::string& directory) noexcept {
  try {
    mark_output_directory(directory, "failed");
  } catch (...) {  // the disk that failed the output may refuse this too
  }
}

}  // namespace pellicle
