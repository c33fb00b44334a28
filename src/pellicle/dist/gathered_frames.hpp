#pragma once
//! Membrane frames of a distributed run. A frame estimator works on a body's points in the
//! order they were generated (connectivity frames take a point's neighbours in that order;
//! the others settle ties and sum over neighbours in it), and migration reorders a rank's
//! points. So each rank sends its points of a membrane body, with their index in the body as
//! built, their position and their previous frame, to every rank; each rank puts the whole
//! body back in generation order, runs the body's own estimator on it as one process would,
//! and keeps its points' frames. Every rank computes bitwise the frames of one process.
//! The cost is the whole membrane on every rank each step: (1 + 3D) doubles per membrane
//! point gathered, and the estimator's work for the whole body (docs/theory/scaling.md).

#include <memory>
#include <vector>

#include "pellicle/dist/communicator.hpp"
#include "pellicle/mpm/particles.hpp"

namespace pellicle {

template <int D>
class GatheredFrames final : public FrameEstimator<D> {
 public:
  //! `whole`: the body's estimator; `points`: this rank's points, whose `index` column holds
  //! each point's index in its body as built; `count`: the body's points on all ranks.
  GatheredFrames(const Communicator& world, std::shared_ptr<FrameEstimator<D>> whole,
                 const Particles<D>& points, Column<double> index, long count);

  void estimate(const std::vector<Vec<D>>& position, long begin, long end,
                std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) override;

 private:
  const Communicator& world_;
  std::shared_ptr<FrameEstimator<D>> whole_;
  const Particles<D>& points_;
  Column<double> index_;
  std::vector<Vec<D>> position_, normal_, tangent_;  //!< the whole body, in generation order
};

//! Give every membrane body of `points` (built whole on every rank, not yet split; `index`
//! its column_names::body_index) a GatheredFrames estimator around its own.
template <int D>
void gather_membrane_frames(const Communicator& world, Particles<D>& points, Column<double> index);

extern template class GatheredFrames<2>;
extern template class GatheredFrames<3>;
extern template void gather_membrane_frames<2>(const Communicator&, Particles<2>&, Column<double>);
extern template void gather_membrane_frames<3>(const Communicator&, Particles<3>&, Column<double>);

}  // namespace pellicle
