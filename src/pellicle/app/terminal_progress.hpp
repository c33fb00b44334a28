#pragma once
//! Progress on stderr: a redrawn bar with ETA on a terminal, a line every 10% otherwise.

#include <chrono>

#include "pellicle/core/progress.hpp"

namespace pellicle {

class TerminalProgress final : public ProgressListener {
 public:
  explicit TerminalProgress(bool interactive) : interactive_(interactive) {}
  void update(const ProgressReport& report) override;
  void finish(const ProgressReport& report) override;

 private:
  void draw(const ProgressReport& report);
  bool interactive_;
  int last_decile_ = 0;
  double last_draw_ = -1.0;
};

}  // namespace pellicle
