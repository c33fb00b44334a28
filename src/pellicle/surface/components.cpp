#include "pellicle/surface/components.hpp"

#include <numeric>
#include <vector>

namespace pellicle {

int connected_parts(const NeighbourLists& neighbours, const NeighbourLists* more) {
  // Union–find with path halving over the links i–j of the lists.
  const std::size_t n = neighbours.points();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&parent](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  int parts = static_cast<int>(n);
  for (const NeighbourLists* lists : {&neighbours, more}) {
    if (!lists || lists->points() != n) continue;
    for (std::size_t i = 0; i < n; ++i)
      for (long k = lists->begin(i); k < lists->end(i); ++k) {
        const int a = root(static_cast<int>(i)), b = root(lists->index[k]);
        if (a != b) {
          parent[a] = b;
          --parts;
        }
      }
  }
  return parts;
}

}  // namespace pellicle
