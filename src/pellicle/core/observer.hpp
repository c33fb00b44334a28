#pragma once
//! The one observer protocol of both engines (MPM and surface): called by the engine at the
//! end of every step (DESIGN.md stage `observe`), for output writers, probes and progress.

namespace pellicle {

template <class Run>
class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void after_step(const Run& run) = 0;
};

}  // namespace pellicle
