#pragma once
//! The first failure (lowest index) met inside an OpenMP loop, to be thrown after the loop:
//! an exception must not leave a parallel region (the program would end), and the lowest
//! index makes the report the same for any number of threads.

namespace pellicle {

class LoopFailure {
 public:
  //! Thread-safe; keeps the lowest index and its detail (a count, a status code).
  void record(long index, int detail) {
#pragma omp critical(pellicle_loop_failure)
    if (index_ < 0 || index < index_) {
      index_ = index;
      detail_ = detail;
    }
  }
  bool failed() const {
    return index_ >= 0;
  }
  long index() const {
    return index_;
  }
  int detail() const {
    return detail_;
  }

 private:
  long index_ = -1;
  int detail_ = 0;
};

}  // namespace pellicle
