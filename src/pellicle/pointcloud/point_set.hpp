#pragma once
//! A read-only view of points for the point-cloud algorithms: positions, each point's
//! smoothing length h_i (its neighbourhood radius), and a generation number that changes
//! whenever points are added or removed (so cached structures know they are stale). The
//! meshfree surfaces' PointCloud converts to it; other point sets can build one.

#include <cstddef>
#include <vector>

#include "pellicle/core/types.hpp"

namespace pellicle {

template <int D>
struct PointSet {
  const std::vector<Vec<D>>& position;
  const std::vector<double>& smoothing_length;
  long generation = 0;
  std::size_t size() const { return position.size(); }
};

}  // namespace pellicle
