#pragma once
//! The observer that reports a run's progress after every step, for MPM and surface runs
//! alike: `Run` has time(), step_count() and settings().end_time.

#include <algorithm>
#include <chrono>

#include "pellicle/core/observer.hpp"
#include "pellicle/core/progress.hpp"

namespace pellicle {

template <class Run>
class ProgressObserver final : public RunObserver<Run> {
 public:
  ProgressObserver(ProgressListener* listener, std::chrono::steady_clock::time_point start)
      : listener_(listener), start_(start) {}
  void after_step(const Run& s) override {
    if (listener_) listener_->update(report(s));
  }
  ProgressReport report(const Run& s) const {
    ProgressReport r;
    r.fraction = std::min(1.0, s.time() / s.settings().end_time);
    r.time = s.time();
    r.step = s.step_count();
    r.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return r;
  }

 private:
  ProgressListener* listener_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace pellicle
