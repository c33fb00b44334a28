#include "pellicle/surface/components.hpp"

#include "pellicle/pointcloud/union_find.hpp"

namespace pellicle {

int connected_parts(const NeighbourLists& neighbours, const NeighbourLists* more) {
  const std::size_t n = neighbours.points();
  UnionFind sets(n);
  int parts = static_cast<int>(n);
  for (const NeighbourLists* lists : {&neighbours, more}) {
    if (!lists || lists->points() != n) continue;
    for (std::size_t i = 0; i < n; ++i)
      for (long k = lists->begin(i); k < lists->end(i); ++k)
        parts -= sets.join(static_cast<int>(i), lists->index[k]);
  }
  return parts;
}

}  // namespace pellicle
