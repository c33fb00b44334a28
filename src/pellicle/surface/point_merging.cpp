// §3.5: points closer than r_min h merged into one, boundary points kept.
#include <algorithm>
#include <tuple>

#include "pellicle/surface/chambers.hpp"
#include "pellicle/surface/management_steps.hpp"
#include "pellicle/surface/mls_interpolation.hpp"
#include "pellicle/surface/placement.hpp"

namespace pellicle {

namespace {

struct ClosePair {
  double distance;
  int i, j;  // i < j
  bool operator<(const ClosePair& o) const {
    return std::tie(distance, i, j) < std::tie(o.distance, o.i, o.j);
  }
};

//! Every pair closer than r_min max(h_i, h_j), closest first. The lists hold the points
//! within r_min h_i of each point i; a pair is in the list of the point with the larger h.
template <int D>
void close_pairs(const PointCloud<D>& cloud, const NeighbourLists& close,
                 std::vector<ClosePair>& pairs) {
  pairs.clear();
  for (std::size_t i = 0; i < cloud.size(); ++i)
    for (long k = close.begin(i) + 1; k < close.end(i); ++k) {
      const int j = close.index[k];
      const int a = std::min(static_cast<int>(i), j), b = std::max(static_cast<int>(i), j);
      pairs.push_back({(cloud.position[a] - cloud.position[b]).norm(), a, b});
    }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(
      std::unique(pairs.begin(), pairs.end(),
                  [](const ClosePair& p, const ClosePair& q) { return p.i == q.i && p.j == q.j; }),
      pairs.end());
}

//! One merge: the point kept (which takes the merged place and values) and the one removed.
template <int D>
struct Merge {
  int kept, gone;
  bool boundary;
  Vec<D> boundary_normal;
};

}  // namespace

template <int D>
void merge_close_points(PointCloud<D>& cloud, NeighbourSearch<D>& search,
                        const ManagementOptions& o, double weight_exponent,
                        ManagementReport& report) {
  NeighbourLists close;
  std::vector<ClosePair> pairs;
  std::vector<Merge<D>> merges;
  std::vector<MlsTarget<D>> targets;
  CarriedValues<D> values;
  for (int round = 0; round < o.max_merge_rounds; ++round) {
    search.find(cloud, close, o.r_min);
    if (cloud.has_parts()) split_by_part(cloud, close, nullptr);  // never across parts (§3.6)
    close_pairs(cloud, close, pairs);
    if (pairs.empty()) break;
    // Closest pairs first; a point takes part in one merge per round.
    std::vector<std::uint8_t> taken(cloud.size(), 0);
    merges.clear();
    targets.clear();
    for (const ClosePair& p : pairs) {
      if (taken[p.i] || taken[p.j]) continue;
      taken[p.i] = taken[p.j] = 1;
      const bool bi = cloud.boundary[p.i], bj = cloud.boundary[p.j];
      const int v[2] = {p.i, p.j};
      Merge<D> m{p.i, p.j, bi || bj, Vec<D>::Zero()};
      MlsTarget<D> t;
      if (bi != bj) {
        // A boundary point and an interior point: the interior one goes, the values are
        // interpolated again at the boundary point, which stays where it is.
        m.kept = bi ? p.i : p.j;
        m.gone = bi ? p.j : p.i;
        m.boundary_normal = cloud.boundary_normal[m.kept];
        t = {cloud.position[m.kept], cloud.frame[m.kept], cloud.smoothing_length[m.kept], m.kept};
        ++report.removed;
      } else {
        const Vec<D> n = approximate_normal(cloud, v, 2);  // eq 6 for the pair
        const Vec<D> normal = n.norm() > 1e-3 ? Vec<D>(n.normalized()) : cloud.normal(p.i);
        const Vec<D> mid = 0.5 * (cloud.position[p.i] + cloud.position[p.j]);
        Vec<D> x;
        if (bi) {
          // Two boundary points: merged halfway along the boundary.
          x = boundary_midpoint<D>(cloud, search, p.i, p.j, weight_exponent);
          m.boundary_normal = boundary_normal_between<D>(cloud.boundary_normal[p.i],
                                                         cloud.boundary_normal[p.j], normal);
        } else {
          const bool midway = o.curvature_rule == CurvatureRule::midway;
          x = o.curvature_correction
                  ? curvature_corrected(cloud, v, nullptr, 2, mid, n, midway ? 0.5 : 1.0)
                  : mid;
        }
        t = {x, frame_with_normal<D>(cloud.frame[p.i], normal, m.boundary_normal),
             0.5 * (cloud.smoothing_length[p.i] + cloud.smoothing_length[p.j]), p.i};
        ++report.merged;
      }
      merges.push_back(m);
      targets.push_back(t);
    }
    report.widened_fits += interpolate_carried(cloud, search, targets, weight_exponent, values);
    std::vector<std::uint8_t> remove(cloud.size(), 0);
    for (std::size_t q = 0; q < merges.size(); ++q) {
      const Merge<D>& m = merges[q];
      const double h = cloud.smoothing_length[m.kept];
      store_carried(values, q, cloud, m.kept);
      if (!(cloud.smoothing_length[m.kept] > 0.0)) cloud.smoothing_length[m.kept] = h;
      cloud.position[m.kept] = targets[q].position;
      cloud.frame[m.kept] = targets[q].frame;
      cloud.boundary[m.kept] = m.boundary ? 1 : 0;
      cloud.boundary_normal[m.kept] = m.boundary_normal;
      remove[m.gone] = 1;
    }
    cloud.remove_points(remove);
  }
}

template void merge_close_points<2>(PointCloud<2>&, NeighbourSearch<2>&, const ManagementOptions&,
                                    double, ManagementReport&);
template void merge_close_points<3>(PointCloud<3>&, NeighbourSearch<3>&, const ManagementOptions&,
                                    double, ManagementReport&);

}  // namespace pellicle
