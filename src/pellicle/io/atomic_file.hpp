#pragma once
//! Whole-file writes that never leave a truncated file behind: the content goes to a
//! temporary name in the same directory, which is renamed over the target when complete.

#include <cstdio>
#include <string>
#include <string_view>

namespace pellicle {

//! Throws std::runtime_error naming the file when it cannot be written.
void write_file_atomically(const std::string& path, std::string_view content);

//! A file written piece by piece under a temporary name and renamed over `path` by
//! commit(); destroyed without commit() (an error on the way) it removes the temporary.
class AtomicFileWriter {
 public:
  explicit AtomicFileWriter(std::string path);  //!< throws std::runtime_error
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  void write(std::string_view text);  //!< throws std::runtime_error (disk full)
  void commit();                      //!< throws std::runtime_error

 private:
  std::string path_, temporary_;
  std::FILE* file_ = nullptr;
};

}  // namespace pellicle
