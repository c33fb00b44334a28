#include "pellicle/dist/halo_frames.hpp"

#include <algorithm>
#include <iterator>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "pellicle/mpm/body_as_built.hpp"

namespace pellicle {

template <int D>
HaloFrames<D>::HaloFrames(const Communicator& world, std::shared_ptr<FrameEstimator<D>> whole,
                          const Particles<D>& points, Column<double> index, long count, double cell)
    : world_(world),
      whole_(std::move(whole)),
      points_(points),
      index_(index),
      count_(count),
      cell_(cell) {}

template <int D>
void HaloFrames<D>::estimate(const std::vector<Vec<D>>& position, long begin, long end,
                             std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) {
  if (from_halo(position, begin, end, normal, tangent)) {
    ++halo_estimates_;
  } else {
    from_whole_body(position, begin, end, normal, tangent);
    ++gathered_estimates_;
  }
}

namespace {

//! A rank's summary of its points of a body: the box around them (lower corner, upper
//! corner; empty when it has none), whether one lacks a frame, the mirror planes they touch.
template <int D>
struct RankSummary {
  static constexpr int width = 2 * D + 2;
  const double* values;
  bool empty() const { return values[0] > values[D]; }
  bool unset() const { return values[2 * D] != 0.0; }
  unsigned planes() const { return static_cast<unsigned>(values[2 * D + 1]); }
  //! Whether x lies in the box widened by `margin`.
  bool near(const Vec<D>& x, double margin) const {
    for (int d = 0; d < D; ++d)
      if (x[d] < values[d] - margin || x[d] > values[D + d] + margin) return false;
    return true;
  }
  //! Whether the box meets `other`'s widened by `margin`.
  bool meets(const RankSummary& other, double margin) const {
    if (empty() || other.empty()) return false;
    for (int d = 0; d < D; ++d)
      if (values[D + d] < other.values[d] - margin || values[d] > other.values[D + d] + margin)
        return false;
    return true;
  }
};

}  // namespace

template <int D>
bool HaloFrames<D>::from_halo(const std::vector<Vec<D>>& position, long begin, long end,
                              std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) {
  const int reach = whole_->reach();
  // The first estimate settles first signs from the whole body (and is the same call on
  // every rank, as is the reach).
  if (reach < 0 || halo_estimates_ + gathered_estimates_ == 0) return false;
  using Summary = RankSummary<D>;
  std::vector<double> mine(Summary::width);
  Vec<D> lower = Vec<D>::Constant(std::numeric_limits<double>::infinity()), upper = -lower;
  bool unset = false;
  for (long p = begin; p < end; ++p) {
    lower = lower.cwiseMin(position[p]);
    upper = upper.cwiseMax(position[p]);
    unset = unset || normal[p].squaredNorm() == 0.0;
  }
  std::copy_n(lower.data(), D, mine.begin());
  std::copy_n(upper.data(), D, mine.begin() + D);
  mine[2 * D] = unset;
  mine[2 * D + 1] = whole_->planes_touched(position, begin, end);
  const std::vector<double> all = world_.all_gather(mine);
  const int ranks = world_.size(), me = world_.rank();
  auto summary = [&](int r) { return Summary{all.data() + r * Summary::width}; };
  part_.count = count_;
  part_.planes = 0;
  for (int r = 0; r < ranks; ++r) {
    if (summary(r).unset()) return false;  // first signs again, from the whole body
    part_.planes |= summary(r).planes();
  }

  // To each rank, this rank's points within reach + 1 cells of its box: a superset of the
  // points in the cells within `reach` of a cell of its points.
  const double margin = (reach + 1) * cell_;
  const std::vector<double>& index = points_[index_];
  to_rank_.resize(ranks);
  for (auto& out : to_rank_) out.clear();
  std::vector<int> neighbours;
  for (int r = 0; r < ranks; ++r) {
    if (r == me) continue;
    const bool send = summary(me).meets(summary(r), margin);
    if (send || summary(r).meets(summary(me), margin)) neighbours.push_back(r);
    if (!send) continue;
    for (long p = begin; p < end; ++p) {
      if (!summary(r).near(position[p], margin)) continue;
      to_rank_[r].push_back(index[p]);
      to_rank_[r].insert(to_rank_[r].end(), position[p].data(), position[p].data() + D);
      to_rank_[r].insert(to_rank_[r].end(), normal[p].data(), normal[p].data() + D);
    }
  }
  for (const auto& out : to_rank_) doubles_sent_ += static_cast<long>(out.size());
  world_.neighbour_all_to_all(to_rank_, from_rank_, neighbours);

  // The part: this rank's points and the halo, in generation order.
  auto by_index = [](const Entry& a, const Entry& b) { return a.index < b.index; };
  // This rank's points in order, sorted anew only when migration has changed them.
  if (!std::equal(index.begin() + begin, index.begin() + end, own_index_.begin(),
                  own_index_.end())) {
    own_index_.assign(index.begin() + begin, index.begin() + end);
    own_order_.resize(end - begin);
    std::iota(own_order_.begin(), own_order_.end(), 0L);
    std::sort(own_order_.begin(), own_order_.end(),
              [&](long a, long b) { return own_index_[a] < own_index_[b]; });
  }
  own_.clear();
  halo_.clear();
  entries_.clear();
  for (long k : own_order_) own_.push_back({static_cast<long>(own_index_[k]), begin + k, nullptr});
  for (const auto& from : from_rank_)
    for (std::size_t k = 0; k < from.size(); k += 1 + 2 * D)
      halo_.push_back({static_cast<long>(from[k]), -1, from.data() + k + 1});
  std::sort(halo_.begin(), halo_.end(), by_index);
  std::merge(own_.begin(), own_.end(), halo_.begin(), halo_.end(), std::back_inserter(entries_),
             by_index);
  const std::size_t n = entries_.size();
  part_.index.resize(n);
  part_.wanted.resize(n);
  position_.resize(n);
  normal_.resize(n);
  tangent_.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Entry& e = entries_[j];
    part_.index[j] = e.index;
    part_.wanted[j] = e.own >= 0;
    if (e.own >= 0) {
      position_[j] = position[e.own];
      normal_[j] = normal[e.own];
      tangent_[j] = tangent[e.own];
    } else {
      position_[j] = Vec<D>(e.record);
      normal_[j] = Vec<D>(e.record + D);
      tangent_[j].setZero();
    }
  }
  const bool complete = n == 0 || whole_->estimate_part(part_, position_, normal_, tangent_);
  if (world_.max(complete ? 0.0 : 1.0) > 0.0) return false;
  for (std::size_t j = 0; j < n; ++j) {
    if (entries_[j].own < 0) continue;
    normal[entries_[j].own] = normal_[j];
    tangent[entries_[j].own] = tangent_[j];
  }
  return true;
}

template <int D>
void HaloFrames<D>::from_whole_body(const std::vector<Vec<D>>& position, long begin, long end,
                                    std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) {
  // Position, normal, tangent of every point of the body, in generation order.
  auto append = [&](long p, std::vector<double>& out) {
    for (const auto* v : {&position[p], &std::as_const(normal)[p], &std::as_const(tangent)[p]})
      out.insert(out.end(), v->data(), v->data() + D);
  };
  const std::vector<double> all = body_as_built(points_, begin, end, 3 * D, append, &world_);
  doubles_sent_ += (end - begin) * (1 + 3 * D) * (world_.size() - 1);
  if (static_cast<long>(all.size()) != count_ * 3 * D)
    throw std::logic_error("a membrane body's points on all ranks are " +
                           std::to_string(all.size() / (3 * D)) + ", not its " +
                           std::to_string(count_));
  position_.resize(count_);
  normal_.resize(count_);
  tangent_.resize(count_);
  for (long i = 0; i < count_; ++i) {
    position_[i] = Vec<D>(all.data() + 3 * D * i);
    normal_[i] = Vec<D>(all.data() + 3 * D * i + D);
    tangent_[i] = Vec<D>(all.data() + 3 * D * i + 2 * D);
  }
  whole_->estimate(position_, 0, count_, normal_, tangent_);
  const std::vector<double>& index = points_[index_];
  for (long p = begin; p < end; ++p) {
    const long i = static_cast<long>(index[p]);
    normal[p] = normal_[i];
    tangent[p] = tangent_[i];
  }
}

template <int D>
std::vector<const HaloFrames<D>*> distribute_membrane_frames(const Communicator& world,
                                                             Particles<D>& points,
                                                             Column<double> index, double cell) {
  std::vector<const HaloFrames<D>*> made;
  for (auto& body : points.bodies)
    if (body.frames) {
      auto frames =
          std::make_shared<HaloFrames<D>>(world, body.frames, points, index, body.built, cell);
      made.push_back(frames.get());
      body.frames = std::move(frames);
    }
  return made;
}

template class HaloFrames<2>;
template class HaloFrames<3>;
template std::vector<const HaloFrames<2>*> distribute_membrane_frames<2>(const Communicator&,
                                                                         Particles<2>&,
                                                                         Column<double>, double);
template std::vector<const HaloFrames<3>*> distribute_membrane_frames<3>(const Communicator&,
                                                                         Particles<3>&,
                                                                         Column<double>, double);

}  // namespace pellicle
