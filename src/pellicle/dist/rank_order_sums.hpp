#pragma once
//! Sums over entries that several ranks of a distributed run hold (shared grid nodes, shared
//! cells). Each rank holds only its own points' share of such an entry. The ranks that share
//! entries send each other their shares, and each adds all of them in rank order: every copy
//! then holds the same sum, bit for bit, and each rank goes on as one process would. One
//! exchange per completion.

#include <vector>

#include "pellicle/dist/communicator.hpp"

namespace pellicle {

class RankOrderSums {
 public:
  //! The entries (storage indices) shared with another rank, in the same order on both sides.
  struct Neighbour {
    int rank;
    std::vector<long> entries;
  };
  //! An array of `components` doubles per entry, entry e at data[e * components].
  struct Array {
    double* data;
    int components;
  };

  //! `neighbours`: lowest rank first.
  RankOrderSums(const Communicator& world, std::vector<Neighbour> neighbours);

  //! Complete the sums of every shared entry of `arrays`.
  void complete(const std::vector<Array>& arrays);
  //! Doubles this rank sent in the last complete().
  long last_doubles_sent() const { return last_sent_; }

 private:
  const Communicator& world_;
  int rank_;
  std::vector<Neighbour> neighbours_;
  std::vector<long> shared_;  //!< every shared entry once
  std::vector<double> own_;   //!< this rank's shares of them
  std::vector<Communicator::Message> outgoing_, incoming_;
  long last_sent_ = 0;
};

}  // namespace pellicle
