// The MPI tests' main: MPI lives for the whole run, and only rank 0 reports.
#include <gtest/gtest.h>

#include "world.hpp"

namespace pellicle {
Communicator* world = nullptr;
}  // namespace pellicle

int main(int argc, char** argv) {
  pellicle::Communicator communicator(argc, argv);
  pellicle::world = &communicator;
  ::testing::InitGoogleTest(&argc, argv);
  if (communicator.rank() != 0) {  // one report, from rank 0
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int failed = RUN_ALL_TESTS();
  return static_cast<int>(communicator.max(failed));
}
