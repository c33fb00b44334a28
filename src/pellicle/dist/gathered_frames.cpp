#include "pellicle/dist/gathered_frames.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "pellicle/mpm/body_as_built.hpp"

namespace pellicle {

template <int D>
GatheredFrames<D>::GatheredFrames(const Communicator& world,
                                  std::shared_ptr<FrameEstimator<D>> whole,
                                  const Particles<D>& points, Column<double> index, long count)
    : world_(world),
      whole_(std::move(whole)),
      points_(points),
      index_(index),
      position_(count),
      normal_(count),
      tangent_(count) {}

template <int D>
void GatheredFrames<D>::estimate(const std::vector<Vec<D>>& position, long begin, long end,
                                 std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) {
  // Position, normal, tangent of every point of the body, in generation order.
  auto append = [&](long p, std::vector<double>& out) {
    for (const auto* v : {&position[p], &std::as_const(normal)[p], &std::as_const(tangent)[p]})
      out.insert(out.end(), v->data(), v->data() + D);
  };
  const std::vector<double> all = body_as_built(points_, begin, end, 3 * D, append, &world_);
  const long count = static_cast<long>(position_.size());
  if (static_cast<long>(all.size()) != count * 3 * D)
    throw std::logic_error("a membrane body's points on all ranks are " +
                           std::to_string(all.size() / (3 * D)) + ", not its " +
                           std::to_string(count));
  for (long i = 0; i < count; ++i) {
    position_[i] = Vec<D>(all.data() + 3 * D * i);
    normal_[i] = Vec<D>(all.data() + 3 * D * i + D);
    tangent_[i] = Vec<D>(all.data() + 3 * D * i + 2 * D);
  }
  whole_->estimate(position_, 0, count, normal_, tangent_);
  const std::vector<double>& index = points_[index_];
  for (long p = begin; p < end; ++p) {
    const long i = static_cast<long>(index[p]);
    normal[p] = normal_[i];
    tangent[p] = tangent_[i];
  }
}

template <int D>
void gather_membrane_frames(const Communicator& world, Particles<D>& points, Column<double> index) {
  for (auto& body : points.bodies)
    if (body.frames)
      body.frames =
          std::make_shared<GatheredFrames<D>>(world, body.frames, points, index, body.built);
}

template class GatheredFrames<2>;
template class GatheredFrames<3>;
template void gather_membrane_frames<2>(const Communicator&, Particles<2>&, Column<double>);
template void gather_membrane_frames<3>(const Communicator&, Particles<3>&, Column<double>);

}  // namespace pellicle
