#include "pellicle/surface/one_ring.hpp"

namespace pellicle {

namespace {

//! A convex polygon in the tangent plane; `site[t]` names the neighbour whose bisector
//! carries the edge from corner t to corner t + 1 (−1 for an edge of the starting square).
struct CellPolygon {
  int count = 0;
  Vec2 corner[kMaxOneRingNeighbours + 4];
  int site[kMaxOneRingNeighbours + 4];
};

//! Keep the part of `in` where p · s ≤ |s|²/2 (the centre's side of the bisector of s).
void clip(const CellPolygon& in, const Vec2& s, int neighbour, CellPolygon& out) {
  const double limit = 0.5 * s.squaredNorm();
  out.count = 0;
  for (int t = 0; t < in.count; ++t) {
    const Vec2& a = in.corner[t];
    const Vec2& b = in.corner[(t + 1) % in.count];
    const double fa = a.dot(s) - limit, fb = b.dot(s) - limit;
    if (fa <= 0.0) {
      out.corner[out.count] = a;
      out.site[out.count++] = in.site[t];
    }
    if ((fa <= 0.0) != (fb <= 0.0)) {
      // The edge crosses the bisector: the crossing starts the bisector's edge when the
      // polygon leaves the half-plane there, else the rest of the edge t.
      out.corner[out.count] = a + fa / (fa - fb) * (b - a);
      out.site[out.count++] = fa <= 0.0 ? neighbour : in.site[t];
    }
  }
}

}  // namespace

template <>
int one_ring<3>(const PointCloud<3>& cloud, const NeighbourLists& nb, std::size_t i, double radius,
                OneRingSimplex* out) {
  const Vec3 x = cloud.position[i];
  const Eigen::Matrix<double, 3, 2> tangents = cloud.frame[i].leftCols<2>();
  CellPolygon cells[2];
  CellPolygon* cell = &cells[0];
  CellPolygon* next = &cells[1];
  // A cell corner farther than `radius` from the centre is the circumcentre of a triangle
  // that cannot contain it (its vertices are within `radius`): a square of half side twice
  // that keeps every corner that matters.
  const double r = 2.0 * radius;
  const Vec2 square[4] = {Vec2(-r, -r), Vec2(r, -r), Vec2(r, r), Vec2(-r, r)};
  cell->count = 4;
  for (int t = 0; t < 4; ++t) {
    cell->corner[t] = square[t];
    cell->site[t] = -1;
  }
  const long last = std::min(nb.end(i), nb.begin(i) + 1 + kMaxOneRingNeighbours);
  for (long k = nb.begin(i) + 1; k < last; ++k) {
    const int j = nb.index[k];
    const Vec2 s = tangents.transpose() * (cloud.position[j] - x);
    const double limit = 0.5 * s.squaredNorm();
    if (limit < 1e-24 * radius * radius) continue;  // projects onto the centre: no bisector
    bool cuts = false;
    for (int t = 0; t < cell->count && !cuts; ++t) cuts = cell->corner[t].dot(s) > limit;
    if (!cuts) continue;
    clip(*cell, s, j, *next);
    std::swap(cell, next);
  }
  int count = 0;
  for (int t = 0; t < cell->count; ++t) {
    const int before = cell->site[(t + cell->count - 1) % cell->count];
    const int after = cell->site[t];
    if (before >= 0 && after >= 0 && before != after) out[count++] = {before, after};
  }
  return count;
}

template <>
int one_ring<2>(const PointCloud<2>& cloud, const NeighbourLists& nb, std::size_t i, double radius,
                OneRingSimplex* out) {
  (void)radius;
  const Vec2 x = cloud.position[i];
  const Vec2 t = cloud.frame[i].col(0);
  int nearest[2] = {-1, -1};
  double distance[2] = {0.0, 0.0};
  for (long k = nb.begin(i) + 1; k < nb.end(i); ++k) {
    const int j = nb.index[k];
    const Vec2 d = cloud.position[j] - x;
    const double s = t.dot(d), r = d.norm();
    if (std::abs(s) < 0.5 * r) continue;  // mostly across the curve, not along it
    const int side = s > 0.0 ? 0 : 1;
    if (nearest[side] < 0 || r < distance[side]) {
      nearest[side] = j;
      distance[side] = r;
    }
  }
  int count = 0;
  for (int side = 0; side < 2; ++side)
    if (nearest[side] >= 0) out[count++] = {nearest[side], -1};
  return count;
}

}  // namespace pellicle
