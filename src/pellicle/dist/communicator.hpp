#pragma once
//! The MPI communicator of a distributed run, behind a small interface so that no header
//! outside dist/ includes mpi.h. Built only with PELLICLE_MPI.

#include <vector>

namespace pellicle {

class Communicator {
 public:
  //! MPI_Init on construction (with the program's arguments), MPI_Finalize on destruction;
  //! one per program.
  Communicator(int& argc, char**& argv);
  ~Communicator();
  Communicator(const Communicator&) = delete;
  Communicator& operator=(const Communicator&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  //! Element-wise sums over the ranks, the same on every rank: each rank's values are added
  //! in rank order, so the result does not depend on the MPI library's reduction tree.
  void sum_in_rank_order(std::vector<double>& values) const;
  void sum(std::vector<long>& values) const;
  double max(double value) const;
  double min(double value) const;

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace pellicle
