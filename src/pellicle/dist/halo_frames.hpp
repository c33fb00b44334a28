#pragma once
//! Membrane frames of a distributed run. A frame estimator works on a body's points in the
//! order they were generated (connectivity frames take a point's neighbours in that order;
//! the others settle ties and sum over neighbours in it), and migration reorders a rank's
//! points and spreads a body over the ranks. Each step, for each membrane body:
//!  - halo: when the body's estimator has a reach (FrameEstimator::reach) and every point has
//!    a frame, each rank receives the body's points within reach + 1 cells of the box of its
//!    own (index in the body, position, normal), puts them with its own in generation order
//!    and estimates that part (FrameEstimator::estimate_part). Cost per step: one allgather
//!    of a box per rank, the halo points, one allreduce;
//!  - gather: otherwise (the first estimate, which settles first signs; a point without a
//!    frame; an estimator whose frames depend on the whole body; a part that lacks a mesh
//!    neighbour), each rank sends its points of the body to every rank, and each runs the
//!    estimator on the whole body as one process would. Cost: the whole body on every rank.
//! Either way every rank gets bitwise the frames of one process (docs/theory/scaling.md).

#include <memory>
#include <vector>

#include "pellicle/dist/communicator.hpp"
#include "pellicle/mpm/particles.hpp"

namespace pellicle {

template <int D>
class HaloFrames final : public FrameEstimator<D> {
 public:
  //! `whole`: the body's estimator; `points`: this rank's points, whose `index` column holds
  //! each point's index in its body as built; `count`: the body's points on all ranks;
  //! `cell`: the grid's cell, the estimator's unit of reach.
  HaloFrames(const Communicator& world, std::shared_ptr<FrameEstimator<D>> whole,
             const Particles<D>& points, Column<double> index, long count, double cell);

  void estimate(const std::vector<Vec<D>>& position, long begin, long end,
                std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) override;

  //! Estimates so far from a halo and from the whole body gathered (for tests and reports).
  long halo_estimates() const { return halo_estimates_; }
  long gathered_estimates() const { return gathered_estimates_; }
  //! Doubles this rank has sent for them: halo records, or its points to every other rank.
  long doubles_sent() const { return doubles_sent_; }

 private:
  const Communicator& world_;
  std::shared_ptr<FrameEstimator<D>> whole_;
  const Particles<D>& points_;
  Column<double> index_;
  long count_;
  double cell_;
  long halo_estimates_ = 0, gathered_estimates_ = 0, doubles_sent_ = 0;
  std::vector<Vec<D>> position_, normal_, tangent_;  //!< the part or the whole body, in order
  //! A point of the part: this rank's point `own`, or (own −1) a halo record (position,
  //! normal) from another rank.
  struct Entry {
    long index;  //!< in the body as built
    long own;
    const double* record;
  };
  std::vector<Entry> own_, halo_, entries_;  //!< work arrays of a halo estimate, kept
  BodyPart part_;
  std::vector<std::vector<double>> to_rank_, from_rank_;
  //! This rank's points' indices in the body when last sorted, and their order by index.
  std::vector<double> own_index_;
  std::vector<long> own_order_;

  //! The halo estimate; false (on every rank) when the whole body must be gathered instead.
  bool from_halo(const std::vector<Vec<D>>& position, long begin, long end,
                 std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent);
  void from_whole_body(const std::vector<Vec<D>>& position, long begin, long end,
                       std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent);
};

//! Give every membrane body of `points` (`index` its column_names::body_index) a HaloFrames
//! estimator around its own; `cell` is the grid's. Returns them.
template <int D>
std::vector<const HaloFrames<D>*> distribute_membrane_frames(const Communicator& world,
                                                             Particles<D>& points,
                                                             Column<double> index, double cell);

extern template class HaloFrames<2>;
extern template class HaloFrames<3>;
extern template std::vector<const HaloFrames<2>*> distribute_membrane_frames<2>(const Communicator&,
                                                                                Particles<2>&,
                                                                                Column<double>,
                                                                                double);
extern template std::vector<const HaloFrames<3>*> distribute_membrane_frames<3>(const Communicator&,
                                                                                Particles<3>&,
                                                                                Column<double>,
                                                                                double);

}  // namespace pellicle
