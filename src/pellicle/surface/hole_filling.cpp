// §3.4: hole filling at the circumcentres of large one-ring triangles, with the curvature
// correction of eqs 6–9 and a separate addition between distant boundary points.
#include <omp.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "pellicle/surface/chambers.hpp"
#include "pellicle/surface/management_steps.hpp"
#include "pellicle/surface/mls_interpolation.hpp"
#include "pellicle/surface/one_ring.hpp"
#include "pellicle/surface/placement.hpp"

namespace pellicle {

namespace {

//! A point to be created. `key` names the simplex it fills: its vertices in increasing
//! order, then −1 for a segment of a curve and −2 for a gap between boundary points, so the
//! same triangle seen from its three corners is one candidate.
template <int D>
struct Candidate {
  std::array<int, 3> key;
  Vec<D> position;
  Vec<D> normal;           //!< unit, eq 6
  Vec<D> boundary_normal;  //!< ν of a new boundary point, else zero
  double radius;           //!< circumradius, or half the gap
  double h;                //!< mean smoothing length of the simplex's points
  bool boundary;
  //! An interior point that sits on a boundary gap (added near the boundary before the gap
  //! grew into a hole) and becomes the gap's boundary point, moved to `position`; else −1.
  int promotes = -1;
};

//! A circumsphere counts as a hole only if it holds no point of the cloud: the triangle is
//! then a Delaunay triangle of the whole cloud, not only of the one-ring's neighbourhood.
constexpr double kEmptyTolerance = 1e-9;

template <int D>
bool push_candidate(const PointCloud<D>& cloud, const NeighbourSearch<D>& search,
                    const ManagementOptions& o, const int* v, const double* lambda, int count,
                    const Vec<D>& x_c, double radius, double h, std::vector<Candidate<D>>& out) {
  const bool midway = o.curvature_correction && o.curvature_rule == CurvatureRule::midway;
  Vec<D> n_approx = approximate_normal(cloud, v, count);  // eq 6
  if (midway) {
    n_approx.setZero();
    for (int k = 0; k < count; ++k) n_approx += lambda[k] * cloud.normal(v[k]);
  }
  // The simplex must lie along the surface its points' normals describe: their normals
  // roughly agree, and the triangle (segment) is within 60° of the tangent plane (line).
  // This keeps triangles across a fold or between two nearby sheets out.
  if (n_approx.norm() < 0.5) return false;
  const Vec<D> n_hat = n_approx.normalized();
  if constexpr (D == 3) {
    const Vec3 across = (cloud.position[v[1]] - cloud.position[v[0]])
                            .cross(cloud.position[v[2]] - cloud.position[v[0]])
                            .normalized();
    if (std::abs(across.dot(n_hat)) < 0.5) return false;
  } else {
    const Vec2 along = (cloud.position[v[1]] - cloud.position[v[0]]).normalized();
    if (std::abs(along.dot(n_hat)) > 0.87) return false;
  }
  Vec<D> x = x_c;
  if (o.curvature_correction)  // eqs 7–9
    x = curvature_corrected(cloud, v, midway ? lambda : nullptr, count, x_c, n_approx,
                            midway ? 0.5 : 1.0);
  if (!nothing_within(cloud, search, x, o.r_min * h, nullptr, 0)) return false;
  Candidate<D> c;
  c.key = {v[0], v[1], count == 3 ? v[2] : -1};
  c.position = x;
  c.normal = n_hat;
  c.boundary_normal = Vec<D>::Zero();
  c.radius = radius;
  c.h = h;
  c.boundary = false;
  out.push_back(c);
  return true;
}

//! Surfaces: the triangles of the one-ring of i whose circumradius exceeds the largest hole
//! radius (ManagementOptions::largest_hole_radius) and whose
//! circumcentre lies inside them; never a triangle of three boundary points.
void triangle_candidates(const PointCloud<3>& cloud, const NeighbourSearch<3>& search,
                         const NeighbourLists& nb, std::size_t i, const ManagementOptions& o,
                         std::vector<Candidate<3>>& out) {
  OneRingSimplex ring[kMaxOneRing];
  const int count = one_ring<3>(cloud, nb, i, o.one_ring_radius * cloud.smoothing_length[i], ring);
  for (int t = 0; t < count; ++t) {
    int v[3] = {static_cast<int>(i), ring[t].first, ring[t].second};
    std::sort(v, v + 3);
    if (cloud.boundary[v[0]] && cloud.boundary[v[1]] && cloud.boundary[v[2]]) continue;
    const double h = (cloud.smoothing_length[v[0]] + cloud.smoothing_length[v[1]] +
                      cloud.smoothing_length[v[2]]) /
                     3.0;
    const Circumcircle cc =
        circumcircle(cloud.position[v[0]], cloud.position[v[1]], cloud.position[v[2]]);
    if (!(cc.radius > o.largest_hole_radius(h)) || !cc.inside()) continue;
    if (!nothing_within(cloud, search, cc.centre, cc.radius * (1.0 - kEmptyTolerance), v, 3))
      continue;
    const double lambda[3] = {cc.barycentric[0], cc.barycentric[1], cc.barycentric[2]};
    push_candidate<3>(cloud, search, o, v, lambda, 3, cc.centre, cc.radius, h, out);
  }
}

//! Curves: the segments to the neighbours on either side longer than twice the largest hole
//! radius; never a
//! segment between two boundary points (ends of the curve).
void segment_candidates(const PointCloud<2>& cloud, const NeighbourSearch<2>& search,
                        const NeighbourLists& nb, std::size_t i, const ManagementOptions& o,
                        std::vector<Candidate<2>>& out) {
  OneRingSimplex ring[2];
  const int count = one_ring<2>(cloud, nb, i, o.one_ring_radius * cloud.smoothing_length[i], ring);
  for (int t = 0; t < count; ++t) {
    const int j = ring[t].first;
    int v[2] = {std::min(static_cast<int>(i), j), std::max(static_cast<int>(i), j)};
    if (cloud.boundary[v[0]] && cloud.boundary[v[1]]) continue;
    const double h = 0.5 * (cloud.smoothing_length[v[0]] + cloud.smoothing_length[v[1]]);
    const double radius = 0.5 * (cloud.position[v[1]] - cloud.position[v[0]]).norm();
    if (!(radius > o.largest_hole_radius(h))) continue;
    const Vec2 x_c = 0.5 * (cloud.position[v[0]] + cloud.position[v[1]]);
    if (!nothing_within(cloud, search, x_c, radius * (1.0 - kEmptyTolerance), v, 2)) continue;
    const double lambda[2] = {0.5, 0.5};
    push_candidate<2>(cloud, search, o, v, lambda, 2, x_c, radius, h, out);
  }
}

//! The 1D addition along the boundary of a surface: from boundary point i to the nearest
//! boundary neighbour on either side along the boundary tangent n × ν; a gap longer than
//! twice the largest hole radius gets a point on the boundary curve halfway
//! (boundary_midpoint).
void boundary_candidates(const PointCloud<3>& cloud, const NeighbourSearch<3>& search,
                         const NeighbourLists& nb, std::size_t i, const ManagementOptions& o,
                         double weight_exponent, std::vector<Candidate<3>>& out) {
  const Vec3 along = cloud.normal(i).cross(cloud.boundary_normal[i]);
  if (along.norm() < 0.5) return;  // no ν
  const Vec3 x = cloud.position[i];
  int nearest[2] = {-1, -1};
  double distance[2] = {0.0, 0.0};
  for (long k = nb.begin(i) + 1; k < nb.end(i); ++k) {
    const int j = nb.index[k];
    if (!cloud.boundary[j]) continue;
    const Vec3 d = cloud.position[j] - x;
    const double s = along.dot(d), r = d.norm();
    if (std::abs(s) < 0.5 * r) continue;
    const int side = s > 0.0 ? 0 : 1;
    if (nearest[side] < 0 || r < distance[side]) {
      nearest[side] = j;
      distance[side] = r;
    }
  }
  thread_local std::vector<int> found;
  for (int side = 0; side < 2; ++side) {
    const int j = nearest[side];
    if (j < 0) continue;
    int v[2] = {std::min(static_cast<int>(i), j), std::max(static_cast<int>(i), j)};
    const double h = 0.5 * (cloud.smoothing_length[v[0]] + cloud.smoothing_length[v[1]]);
    const double half = 0.5 * distance[side];
    if (!(half > o.largest_hole_radius(h))) continue;
    // Adjacent along the boundary: no other boundary point on the gap.
    const Vec3 mid = 0.5 * (cloud.position[v[0]] + cloud.position[v[1]]);
    search.around(cloud, mid, half, found);
    bool between = false;
    for (int k : found) between = between || (cloud.boundary[k] && k != v[0] && k != v[1]);
    if (between) continue;
    const Vec3 position = boundary_midpoint<3>(cloud, search, v[0], v[1], weight_exponent);
    // Points within r_min h of the new one: none, or an interior point that takes its place.
    search.around(cloud, position, o.r_min * h, found);
    int occupant = -1;
    bool taken = false;
    double nearest_distance = o.r_min * h;
    for (int k : found) {
      const double r = (cloud.position[k] - position).norm();
      if (r >= o.r_min * h) continue;
      taken = taken || cloud.boundary[k];
      if (r < nearest_distance) {
        occupant = k;
        nearest_distance = r;
      }
    }
    if (taken) continue;
    Candidate<3> c;
    c.promotes = occupant;
    c.key = {v[0], v[1], -2};
    c.position = position;
    c.normal = (cloud.normal(v[0]) + cloud.normal(v[1])).normalized();
    c.boundary_normal = boundary_normal_between<3>(cloud.boundary_normal[v[0]],
                                                   cloud.boundary_normal[v[1]], c.normal);
    c.radius = half;
    c.h = h;
    c.boundary = true;
    out.push_back(c);
  }
}

template <int D>
void point_candidates(const PointCloud<D>& cloud, const NeighbourSearch<D>& search,
                      const NeighbourLists& nb, std::size_t i, const ManagementOptions& o,
                      double weight_exponent, std::vector<Candidate<D>>& out) {
  if constexpr (D == 3) {
    triangle_candidates(cloud, search, nb, i, o, out);
    if (cloud.boundary[i]) boundary_candidates(cloud, search, nb, i, o, weight_exponent, out);
  } else {
    (void)weight_exponent;
    segment_candidates(cloud, search, nb, i, o, out);
  }
}

//! Cells of side `cell` hashed into one integer; distant cells may share a key, which only
//! costs distance checks.
template <int D>
long long cell_key(const Vec<D>& x, double cell, const int* shift = nullptr) {
  long long key = 0;
  for (int d = 0; d < D; ++d) {
    const long long c = static_cast<long long>(std::floor(x[d] / cell)) + (shift ? shift[d] : 0);
    key = (key << 21) | (c & 0x1FFFFF);
  }
  return key;
}

//! The candidates kept, in `order` (largest holes first): each one farther than
//! r_min max(h_p, h_q) from every candidate kept before it.
template <int D>
std::vector<int> spaced(const std::vector<Candidate<D>>& c, const std::vector<int>& order,
                        double r_min) {
  double h_max = 0.0;
  for (const auto& candidate : c) h_max = std::max(h_max, candidate.h);
  const double cell = r_min * h_max;
  std::vector<std::pair<long long, int>> cells(c.size());
  for (std::size_t q = 0; q < c.size(); ++q)
    cells[q] = {cell_key<D>(c[q].position, cell), static_cast<int>(q)};
  std::sort(cells.begin(), cells.end());
  std::vector<std::uint8_t> kept(c.size(), 0);
  std::vector<int> out;
  for (const int q : order) {
    bool free = true;
    int shift[D];
    for (int s = 0; s < (D == 3 ? 27 : 9) && free; ++s) {
      for (int d = 0, r = s; d < D; ++d, r /= 3) shift[d] = r % 3 - 1;
      const long long key = cell_key<D>(c[q].position, cell, shift);
      auto it = std::lower_bound(cells.begin(), cells.end(), std::make_pair(key, -1));
      for (; it != cells.end() && it->first == key && free; ++it) {
        const int p = it->second;
        const double limit = r_min * std::max(c[p].h, c[q].h);
        free = !kept[p] || (c[p].position - c[q].position).squaredNorm() >= limit * limit;
      }
    }
    if (!free) continue;
    kept[q] = 1;
    out.push_back(q);
  }
  return out;
}

}  // namespace

template <int D>
void fill_holes(PointCloud<D>& cloud, NeighbourSearch<D>& search, const ManagementOptions& o,
                double weight_exponent, ManagementReport& report) {
  NeighbourLists nb;
  std::vector<std::vector<Candidate<D>>> found(omp_get_max_threads());
  std::vector<Candidate<D>> all;
  std::vector<MlsTarget<D>> targets;
  CarriedValues<D> values;
  // Pass 1 looks at every point, later passes at the points the previous pass added and the
  // points that have one of them in their neighbourhood: the new triangles all have a new
  // corner, but a triangle need not be in the one-ring of every corner (each projects onto
  // its own tangent plane).
  std::size_t first = 0;
  report.filled = true;
  for (int pass = 0; pass <= o.max_fill_passes; ++pass) {
    search.find(cloud, nb, o.one_ring_radius);
    if (cloud.has_parts()) split_by_part(cloud, nb, nullptr);  // one-rings of one part (§3.6)
    const long n = static_cast<long>(cloud.size());
#pragma omp parallel
    {
      auto& mine = found[omp_get_thread_num()];
      mine.clear();
#pragma omp for schedule(dynamic, 256)
      for (long i = 0; i < n; ++i) {
        bool look = static_cast<std::size_t>(i) >= first;
        for (long k = nb.begin(i) + 1; k < nb.end(i) && !look; ++k)
          look = static_cast<std::size_t>(nb.index[k]) >= first;
        if (look) point_candidates<D>(cloud, search, nb, i, o, weight_exponent, mine);
      }
    }
    all.clear();
    for (const auto& block : found) all.insert(all.end(), block.begin(), block.end());
    std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
    all.erase(std::unique(all.begin(), all.end(),
                          [](const auto& a, const auto& b) { return a.key == b.key; }),
              all.end());
    if (pass == o.max_fill_passes) {  // one look more: are holes left?
      report.filled = all.empty();
      break;
    }
    std::vector<int> order(all.size());
    for (std::size_t q = 0; q < all.size(); ++q) order[q] = static_cast<int>(q);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      return all[a].radius != all[b].radius ? all[a].radius > all[b].radius
                                            : all[a].key < all[b].key;
    });
    const std::vector<int> kept = spaced(all, order, o.r_min);
    if (kept.empty()) break;

    targets.resize(kept.size());
    for (std::size_t q = 0; q < kept.size(); ++q) {
      const Candidate<D>& c = all[kept[q]];
      targets[q] = {c.position,
                    frame_with_normal<D>(cloud.frame[c.key[0]], c.normal, c.boundary_normal), c.h,
                    c.key[0]};
    }
    report.widened_fits += interpolate_carried(cloud, search, targets, weight_exponent, values);
    long promoted = 0;
    for (std::size_t q = 0; q < kept.size(); ++q) {
      const Candidate<D>& c = all[kept[q]];
      std::size_t i;
      if (c.promotes >= 0) {
        i = static_cast<std::size_t>(c.promotes);
        cloud.position[i] = c.position;
        cloud.boundary[i] = 1;
        ++promoted;
      } else {
        i = cloud.add_point(c.position, c.h, c.boundary);
        cloud.inherit_identity(i, static_cast<std::size_t>(c.key[0]));
      }
      store_carried(values, q, cloud, i);
      if (!(cloud.smoothing_length[i] > 0.0)) cloud.smoothing_length[i] = c.h;
      cloud.frame[i] = targets[q].frame;
      cloud.boundary_normal[i] = c.boundary_normal;
    }
    report.added += static_cast<long>(kept.size()) - promoted;
    report.promoted += promoted;
    report.fill_passes = pass + 1;
    first = static_cast<std::size_t>(n);
  }
}

template void fill_holes<2>(PointCloud<2>&, NeighbourSearch<2>&, const ManagementOptions&, double,
                            ManagementReport&);
template void fill_holes<3>(PointCloud<3>&, NeighbourSearch<3>&, const ManagementOptions&, double,
                            ManagementReport&);

}  // namespace pellicle
