#pragma once
//! Neighbourhoods S_i of a point cloud: the points within the smoothing length h_i of x_i,
//! distances taken in the embedding space (Suchde & Kuhnert §2, §3.3). Found with a k-d tree
//! (nanoflann) that is kept while the points move less than a set fraction of h and rebuilt
//! after that or when points are added or removed.

#include <memory>
#include <vector>

#include "pellicle/pointcloud/point_set.hpp"

namespace pellicle {

//! Compressed neighbour lists: the neighbours of point i are index[offset[i] … offset[i+1]),
//! the point itself first.
struct NeighbourLists {
  std::vector<long> offset{0};
  std::vector<int> index;
  std::size_t points() const { return offset.size() - 1; }
  long begin(std::size_t i) const { return offset[i]; }
  long end(std::size_t i) const { return offset[i + 1]; }
  int count(std::size_t i) const { return static_cast<int>(offset[i + 1] - offset[i]); }
};

template <int D>
class NeighbourSearch {
 public:
  //! The tree is rebuilt once some point has moved more than `rebuild_fraction` times the
  //! smallest smoothing length since it was built.
  explicit NeighbourSearch(double rebuild_fraction = 0.25);
  ~NeighbourSearch();
  NeighbourSearch(const NeighbourSearch&) = delete;
  NeighbourSearch& operator=(const NeighbourSearch&) = delete;

  //! S_i for every point of `cloud`, within h_i (scaled by `radius_factor`). A point with
  //! fewer than `minimum` neighbours there (a corner of a surface's boundary, a stretched
  //! region not yet refilled) takes its `minimum` nearest points instead, so that its
  //! stencil still has points enough for a quadratic fit (gfdm.hpp widens its weight to
  //! match).
  void find(const PointSet<D>& cloud, NeighbourLists& lists, double radius_factor = 1.0,
            int minimum = 0);
  //! Points of `cloud` within `radius` of `x` (any place, not only cloud points), for the
  //! cloud as the last `find` saw it (same points, positions since then unchanged). Safe to
  //! call from several threads at once.
  void around(const PointSet<D>& cloud, const Vec<D>& x, double radius,
              std::vector<int>& found) const;
  long rebuilds() const { return rebuilds_; }

 private:
  void refresh(const PointSet<D>& cloud);
  struct Tree;
  std::unique_ptr<Tree> tree_;
  double rebuild_fraction_;
  double drift_ = 0.0;  //!< largest distance of a point from its place in the tree
  long generation_ = -1;
  long rebuilds_ = 0;
};

}  // namespace pellicle
