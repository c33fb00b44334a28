#pragma once
//! Reductions over the ranks of a distributed run, as the engines see them. A run on one
//! process has none (the engines then reduce nothing); dist/ implements this over MPI. Every
//! call is collective: all ranks make the same calls in the same order.

#include <vector>

namespace pellicle {

class Collective {
 public:
  virtual ~Collective() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  //! Element-wise sums, the same on every rank and independent of the library's reduction
  //! tree (each rank's values are added in rank order).
  virtual void sum_in_rank_order(std::vector<double>& values) const = 0;
  virtual void sum(std::vector<long>& values) const = 0;
  virtual double max(double value) const = 0;
  virtual void max(std::vector<double>& values) const = 0;  //!< element-wise
  virtual double min(double value) const = 0;
  //! Every rank's `mine`, joined in rank order, on every rank.
  virtual std::vector<double> all_gather(const std::vector<double>& mine) const = 0;
};

}  // namespace pellicle
