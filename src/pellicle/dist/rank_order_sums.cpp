#include "pellicle/dist/rank_order_sums.hpp"

#include <algorithm>

namespace pellicle {

namespace {

int doubles_per_entry(const std::vector<RankOrderSums::Array>& arrays) {
  int n = 0;
  for (const auto& a : arrays) n += a.components;
  return n;
}

void pack(const std::vector<RankOrderSums::Array>& arrays, const std::vector<long>& entries,
          std::vector<double>& out) {
  out.resize(entries.size() * doubles_per_entry(arrays));
  double* o = out.data();
  for (long e : entries)
    for (const auto& [data, c] : arrays)
      for (int i = 0; i < c; ++i) *o++ = data[e * c + i];
}

void add(const std::vector<RankOrderSums::Array>& arrays, const std::vector<long>& entries,
         const std::vector<double>& in) {
  const double* v = in.data();
  for (long e : entries)
    for (const auto& [data, c] : arrays)
      for (int i = 0; i < c; ++i) data[e * c + i] += *v++;
}

void clear(const std::vector<RankOrderSums::Array>& arrays, const std::vector<long>& entries) {
  for (long e : entries)
    for (const auto& [data, c] : arrays)
      for (int i = 0; i < c; ++i) data[e * c + i] = 0.0;
}

}  // namespace

RankOrderSums::RankOrderSums(const Communicator& world, std::vector<Neighbour> neighbours)
    : world_(world), rank_(world.rank()), neighbours_(std::move(neighbours)) {
  for (const auto& n : neighbours_)
    shared_.insert(shared_.end(), n.entries.begin(), n.entries.end());
  std::sort(shared_.begin(), shared_.end());
  shared_.erase(std::unique(shared_.begin(), shared_.end()), shared_.end());
  outgoing_.resize(neighbours_.size());
  incoming_.resize(neighbours_.size());
}

void RankOrderSums::complete(const std::vector<Array>& arrays) {
  last_sent_ = 0;
  for (std::size_t k = 0; k < neighbours_.size(); ++k) {
    outgoing_[k].rank = incoming_[k].rank = neighbours_[k].rank;
    pack(arrays, neighbours_[k].entries, outgoing_[k].values);
    incoming_[k].values.resize(outgoing_[k].values.size());
    last_sent_ += static_cast<long>(outgoing_[k].values.size());
  }
  world_.exchange(outgoing_, incoming_);
  // Every shared entry's sum in rank order over the ranks that hold it (0 + a = a exactly):
  // the lower ranks' shares, this rank's, the higher ranks'.
  pack(arrays, shared_, own_);
  clear(arrays, shared_);
  std::size_t k = 0;
  for (; k < neighbours_.size() && neighbours_[k].rank < rank_; ++k)
    add(arrays, neighbours_[k].entries, incoming_[k].values);
  add(arrays, shared_, own_);
  for (; k < neighbours_.size(); ++k) add(arrays, neighbours_[k].entries, incoming_[k].values);
}

}  // namespace pellicle
