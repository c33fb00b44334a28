#include "pellicle/surface/chambers.hpp"

#include <algorithm>
#include <map>
#include <vector>

#include "pellicle/pointcloud/union_find.hpp"

namespace pellicle {

template <int D>
void split_by_part(const PointCloud<D>& cloud, NeighbourLists& lists, NeighbourLists* external) {
  const std::size_t n = lists.points();
  NeighbourLists own;
  own.offset.assign(n + 1, 0);
  own.index.reserve(lists.index.size());
  if (external) {
    external->offset.assign(n + 1, 0);
    external->index.clear();
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec<D> normal = cloud.normal(i);
    for (long k = lists.begin(i); k < lists.end(i); ++k) {
      const int j = lists.index[k];
      if (cloud.on_part(j, i, normal) || j == static_cast<int>(i))
        own.index.push_back(j);
      else if (external)
        external->index.push_back(j);
    }
    own.offset[i + 1] = static_cast<long>(own.index.size());
    if (external) external->offset[i + 1] = static_cast<long>(external->index.size());
  }
  lists = std::move(own);
}

template <int D>
long top_up_parts(const PointCloud<D>& cloud, const NeighbourSearch<D>& search,
                  NeighbourLists& lists, int minimum, std::vector<std::uint8_t>& short_of) {
  const std::size_t n = lists.points();
  short_of.assign(n, 0);
  bool any = false;
  for (std::size_t i = 0; i < n && !any; ++i) any = lists.count(i) - 1 < minimum;
  if (!any) return 0;
  long still_short = 0;
  NeighbourLists topped;
  topped.offset.assign(n + 1, 0);
  topped.index.reserve(lists.index.size());
  std::vector<int> found;
  std::vector<std::pair<double, int>> by_distance;
  for (std::size_t i = 0; i < n; ++i) {
    if (lists.count(i) - 1 >= minimum) {
      topped.index.insert(topped.index.end(), lists.index.begin() + lists.begin(i),
                          lists.index.begin() + lists.end(i));
    } else {
      const Vec<D> x = cloud.position[i];
      search.around(cloud, x, 2.0 * cloud.smoothing_length[i], found);
      by_distance.clear();
      for (int j : found)
        if (j != static_cast<int>(i) && cloud.same_part(i, j))
          by_distance.emplace_back((cloud.position[j] - x).squaredNorm(), j);
      const std::size_t keep = std::min<std::size_t>(by_distance.size(), minimum);
      std::partial_sort(by_distance.begin(), by_distance.begin() + keep, by_distance.end());
      topped.index.push_back(static_cast<int>(i));  // itself first
      for (std::size_t m = 0; m < keep; ++m) topped.index.push_back(by_distance[m].second);
      if (static_cast<int>(keep) < minimum) {
        short_of[i] = 1;
        ++still_short;
      }
    }
    topped.offset[i + 1] = static_cast<long>(topped.index.size());
  }
  lists = std::move(topped);
  return still_short;
}

template <int D>
ChamberReport split_chambers(PointCloud<D>& cloud, const NeighbourLists& own,
                             const NeighbourLists& external, long smallest_part) {
  const std::size_t n = cloud.size();
  // Parts: linked through S_i. Chambers: linked within h, S_i or S_i^ext, in one chamber
  // (two spheres that delete contact joined are one chamber though kept apart as parts).
  UnionFind parts(n), chambers(n);
  for (std::size_t i = 0; i < n && i < own.points(); ++i)
    for (long k = own.begin(i); k < own.end(i); ++k) {
      parts.join(static_cast<int>(i), own.index[k]);
      chambers.join(static_cast<int>(i), own.index[k]);
    }
  for (std::size_t i = 0; i < n && i < external.points(); ++i)
    for (long k = external.begin(i); k < external.end(i); ++k)
      if (cloud.chamber[external.index[k]] == cloud.chamber[i])
        chambers.join(static_cast<int>(i), external.index[k]);
  ChamberReport report;
  // Debris: parts too small to carry a normal, whatever they touch.
  std::vector<long> part_size(n, 0);
  for (std::size_t i = 0; i < n; ++i) ++part_size[parts.root(static_cast<int>(i))];
  std::vector<std::uint8_t> remove(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (part_size[parts.root(static_cast<int>(i))] < smallest_part) {
      remove[i] = 1;
      ++report.debris;
    }
  // Components per chamber, by size, without the debris.
  std::map<int, std::map<int, long>> sizes;  // chamber → component root → points
  for (std::size_t i = 0; i < n; ++i)
    if (!remove[i]) ++sizes[cloud.chamber[i]][chambers.root(static_cast<int>(i))];
  int next = sizes.empty() ? 0 : sizes.rbegin()->first + 1;
  std::map<int, int> relabel;  // component root → new chamber
  for (const auto& [chamber, components] : sizes) {
    if (components.size() < 2) continue;
    ++report.split;
    // The largest component (the lowest root among equals) keeps the chamber's id.
    const auto largest =
        std::max_element(components.begin(), components.end(), [](const auto& a, const auto& b) {
          return a.second != b.second ? a.second < b.second : a.first > b.first;
        });
    for (const auto& [component, count] : components)
      if (component != largest->first) relabel[component] = next++;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto it = relabel.find(chambers.root(static_cast<int>(i)));
    if (it != relabel.end()) cloud.chamber[i] = it->second;
  }
  cloud.remove_points(remove);
  return report;
}

template long top_up_parts<2>(const PointCloud<2>&, const NeighbourSearch<2>&, NeighbourLists&, int,
                              std::vector<std::uint8_t>&);
template long top_up_parts<3>(const PointCloud<3>&, const NeighbourSearch<3>&, NeighbourLists&, int,
                              std::vector<std::uint8_t>&);
template void split_by_part<2>(const PointCloud<2>&, NeighbourLists&, NeighbourLists*);
template void split_by_part<3>(const PointCloud<3>&, NeighbourLists&, NeighbourLists*);
template ChamberReport split_chambers<2>(PointCloud<2>&, const NeighbourLists&,
                                         const NeighbourLists&, long);
template ChamberReport split_chambers<3>(PointCloud<3>&, const NeighbourLists&,
                                         const NeighbourLists&, long);

}  // namespace pellicle
