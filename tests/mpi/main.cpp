// The MPI tests' main: MPI lives for the whole run, and only rank 0 reports.
#include <gtest/gtest.h>

#include <cstdio>

#include "world.hpp"

namespace pellicle {
Communicator* world = nullptr;
}  // namespace pellicle

namespace {

//! Prints a failure where it happens, on a rank that does not report.
class FailuresOfThisRank final : public ::testing::EmptyTestEventListener {
 public:
  explicit FailuresOfThisRank(int rank) : rank_(rank) {}
  void OnTestPartResult(const ::testing::TestPartResult& result) override {
    if (result.failed())
      std::printf("rank %d: %s:%d: Failure\n%s\n", rank_,
                  result.file_name() ? result.file_name() : "?", result.line_number(),
                  result.summary());
  }

 private:
  int rank_;
};

}  // namespace

int main(int argc, char** argv) {
  pellicle::Communicator communicator(argc, argv);
  pellicle::world = &communicator;
  ::testing::InitGoogleTest(&argc, argv);
  if (communicator.rank() != 0) {  // one report, from rank 0, and other ranks' failures
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    listeners.Append(new FailuresOfThisRank(communicator.rank()));
  }
  const int failed = RUN_ALL_TESTS();
  return static_cast<int>(communicator.max(failed));
}
