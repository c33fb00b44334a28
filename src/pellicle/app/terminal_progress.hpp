#pragma once
//! Progress on stderr: a redrawn bar with ETA on a terminal; otherwise (a log file) a line
//! with the ETA at every 10 % of simulated time and at least once a minute of wall time.

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
  double last_line_ = 0.0;  //!< wall time of the last line (log output)
};

}  // namespace pellicle
