#include "pellicle/dist/gathered_frames.hpp"

#include <stdexcept>
#include <string>

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
  constexpr int kRecord = 1 + 3 * D;  // index, position, normal, tangent
  const std::vector<double>& index = points_[index_];
  mine_.clear();
  auto append = [this](const Vec<D>& v) { mine_.insert(mine_.end(), v.data(), v.data() + D); };
  for (long p = begin; p < end; ++p) {
    mine_.push_back(index[p]);
    append(position[p]), append(normal[p]), append(tangent[p]);
  }
  const std::vector<double> all = world_.all_gather(mine_);
  const long count = static_cast<long>(position_.size());
  if (static_cast<long>(all.size()) != count * kRecord)
    throw std::logic_error("a membrane body's points on all ranks are " +
                           std::to_string(all.size() / kRecord) + ", not its " +
                           std::to_string(count));
  for (std::size_t r = 0; r < all.size(); r += kRecord) {
    const long i = static_cast<long>(all[r]);
    position_[i] = Eigen::Map<const Vec<D>>(&all[r + 1]);
    normal_[i] = Eigen::Map<const Vec<D>>(&all[r + 1 + D]);
    tangent_[i] = Eigen::Map<const Vec<D>>(&all[r + 1 + 2 * D]);
  }
  whole_->estimate(position_, 0, count, normal_, tangent_);
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
          std::make_shared<GatheredFrames<D>>(world, body.frames, points, index, body.count());
}

template class GatheredFrames<2>;
template class GatheredFrames<3>;
template void gather_membrane_frames<2>(const Communicator&, Particles<2>&, Column<double>);
template void gather_membrane_frames<3>(const Communicator&, Particles<3>&, Column<double>);

}  // namespace pellicle
