#pragma once
//! The MPI communicator of a distributed run, behind a small interface so that no header
//! outside dist/ includes mpi.h. Built only with PELLICLE_MPI.

#include <vector>

#include "pellicle/core/collective.hpp"

namespace pellicle {

class Communicator final : public Collective {
 public:
  //! MPI_Init on construction (with the program's arguments), MPI_Finalize on destruction;
  //! one per program.
  Communicator(int& argc, char**& argv);
  ~Communicator();
  Communicator(const Communicator&) = delete;
  Communicator& operator=(const Communicator&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  //! Ranks of the run on this machine (they share its cores).
  int ranks_on_this_machine() const { return local_size_; }

  void sum_in_rank_order(std::vector<double>& values) const override;
  void sum(std::vector<long>& values) const override;
  double max(double value) const override;
  void max(std::vector<double>& values) const override;
  double min(double value) const override;

  //! Point-to-point: send each outgoing buffer to its rank and receive each incoming buffer
  //! (sized by the caller) from its rank, all at once; returns when all have arrived.
  struct Message {
    int rank = 0;
    std::vector<double> values;
  };
  void exchange(const std::vector<Message>& outgoing, std::vector<Message>& incoming) const;
  //! Every rank sends to_rank[r] to rank r and gets what each rank sent it, in from_rank[r].
  void all_to_all(const std::vector<std::vector<double>>& to_rank,
                  std::vector<std::vector<double>>& from_rank) const;
  //! The same when ranks mostly send to their `neighbours` (a symmetric relation: each of a
  //! rank's neighbours lists it too): the counts go only between neighbours, after one
  //! allreduce that tells whether any rank sends beyond them (then all_to_all). O(neighbours)
  //! messages and O(log P) latency instead of the O(P) all-to-all of counts.
  void neighbour_all_to_all(const std::vector<std::vector<double>>& to_rank,
                            std::vector<std::vector<double>>& from_rank,
                            const std::vector<int>& neighbours) const;
  std::vector<double> all_gather(const std::vector<double>& mine) const override;
  //! Stop every rank of the run with this exit code (a failure one rank found, which the
  //! others, waiting in a collective call, cannot learn of).
  [[noreturn]] void abort(int exit_code) const;

 private:
  int rank_ = 0, size_ = 1, local_size_ = 1;
};

}  // namespace pellicle
