#pragma once
//! Progress of a long computation, reported to whoever drives it (the command line draws a
//! bar; a library user may ignore it).

namespace pellicle {

struct ProgressReport {
  double fraction = 0.0;  //!< 0 … 1
  double time = 0.0;      //!< simulated time reached
  long step = 0;
  double wall_seconds = 0.0;  //!< since the run started
};

class ProgressListener {
 public:
  virtual ~ProgressListener() = default;
  virtual void update(const ProgressReport& report) = 0;
  virtual void finish(const ProgressReport& report) = 0;
};

}  // namespace pellicle
