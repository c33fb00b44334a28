#include "pellicle/pointcloud/neighbour_search.hpp"

#include <omp.h>

#include <algorithm>
#include <nanoflann.hpp>

namespace pellicle {

template <int D>
struct NeighbourSearch<D>::Tree {
  //! The positions the tree was built on; points have moved at most `drift_` from them.
  struct Snapshot {
    std::vector<Vec<D>> x;
    std::size_t kdtree_get_point_count() const { return x.size(); }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return x[i][d]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
      return false;
    }
  };
  using Index = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Snapshot>,
                                                    Snapshot, D, unsigned>;
  Snapshot snapshot;
  std::unique_ptr<Index> index;

  void build(const std::vector<Vec<D>>& x) {
    snapshot.x = x;
    index = std::make_unique<Index>(D, snapshot, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    index->buildIndex();
  }
  //! The k points nearest q in the snapshot (indices only).
  void nearest(const Vec<D>& q, unsigned k, std::vector<unsigned>& index,
               std::vector<double>& distance) const {
    index.resize(k);
    distance.resize(k);
    index.resize(index_knn(q, k, index.data(), distance.data()));
  }
  std::size_t index_knn(const Vec<D>& q, unsigned k, unsigned* i, double* d) const {
    return this->index->knnSearch(q.data(), k, i, d);
  }
  //! Candidates within `radius` of q in the snapshot.
  void query(const Vec<D>& q, double radius,
             std::vector<std::pair<unsigned, double>>& matches) const {
    matches.clear();
    nanoflann::SearchParams params;
    params.sorted = false;
    index->radiusSearch(q.data(), radius * radius, matches, params);
  }
};

template <int D>
NeighbourSearch<D>::NeighbourSearch(double rebuild_fraction)
    : rebuild_fraction_(rebuild_fraction) {}
template <int D>
NeighbourSearch<D>::~NeighbourSearch() = default;

template <int D>
void NeighbourSearch<D>::refresh(const PointSet<D>& cloud) {
  const std::size_t n = cloud.size();
  bool rebuild = !tree_ || generation_ != cloud.generation || tree_->snapshot.x.size() != n;
  if (!rebuild) {
    double drift = 0.0, h_min = 1e300;
#pragma omp parallel for reduction(max : drift) reduction(min : h_min)
    for (std::size_t i = 0; i < n; ++i) {
      drift = std::max(drift, (cloud.position[i] - tree_->snapshot.x[i]).norm());
      h_min = std::min(h_min, cloud.smoothing_length[i]);
    }
    drift_ = drift;
    rebuild = drift > rebuild_fraction_ * h_min;
  }
  if (rebuild) {
    if (!tree_) tree_ = std::make_unique<Tree>();
    tree_->build(cloud.position);
    generation_ = cloud.generation;
    drift_ = 0.0;
    ++rebuilds_;
  }
}

template <int D>
void NeighbourSearch<D>::find(const PointSet<D>& cloud, NeighbourLists& lists, double radius_factor,
                              int minimum) {
  refresh(cloud);
  const std::size_t n = cloud.size();
  lists.offset.assign(n + 1, 0);
  // Each thread takes one contiguous block of points, so the blocks joined in thread order
  // are the lists in point order.
  std::vector<std::vector<int>> found(omp_get_max_threads());
#pragma omp parallel
  {
    auto& mine = found[omp_get_thread_num()];
    mine.clear();
    std::vector<std::pair<unsigned, double>> matches;
    std::vector<unsigned> closest;
    std::vector<double> closest_distance;
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const Vec<D>& x = cloud.position[i];
      const double h = radius_factor * cloud.smoothing_length[i];
      tree_->query(x, h + drift_, matches);
      const std::size_t start = mine.size();
      mine.push_back(static_cast<int>(i));
      for (const auto& [j, ignored] : matches)
        if (j != i && (cloud.position[j] - x).squaredNorm() <= h * h)
          mine.push_back(static_cast<int>(j));
      if (static_cast<int>(mine.size() - start) - 1 < minimum) {
        // The nearest points instead; a few extra candidates cover the drift.
        mine.resize(start + 1);
        const unsigned k = std::min<std::size_t>(n, minimum + 9);
        tree_->nearest(x, k, closest, closest_distance);
        std::vector<std::pair<double, unsigned>> by_distance;
        for (unsigned j : closest)
          if (j != i) by_distance.emplace_back((cloud.position[j] - x).squaredNorm(), j);
        std::sort(by_distance.begin(), by_distance.end());
        for (std::size_t m = 0; m < by_distance.size() && m < std::size_t(minimum); ++m)
          mine.push_back(static_cast<int>(by_distance[m].second));
      }
      std::sort(mine.begin() + start + 1, mine.end());  // independent of the tree's order
      lists.offset[i + 1] = static_cast<long>(mine.size() - start);
    }
  }
  for (std::size_t i = 0; i < n; ++i) lists.offset[i + 1] += lists.offset[i];
  lists.index.clear();
  lists.index.reserve(lists.offset[n]);
  for (const auto& block : found) lists.index.insert(lists.index.end(), block.begin(), block.end());
}

template <int D>
void NeighbourSearch<D>::around(const PointSet<D>& cloud, const Vec<D>& x, double radius,
                                std::vector<int>& out) const {
  thread_local std::vector<std::pair<unsigned, double>> matches;
  tree_->query(x, radius + drift_, matches);
  out.clear();
  for (const auto& [j, ignored] : matches)
    if ((cloud.position[j] - x).squaredNorm() <= radius * radius)
      out.push_back(static_cast<int>(j));
  std::sort(out.begin(), out.end());
}

template class NeighbourSearch<2>;
template class NeighbourSearch<3>;

}  // namespace pellicle
