#include "pellicle/geometry/enclosure.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace pellicle {

namespace {

template <int D>
Vec<D> reflect(Vec<D> x, const MirrorPlane& plane) {
  x[plane.axis] = 2.0 * plane.position - x[plane.axis];
  return x;
}

template <int D>
std::string where(const Vec<D>& x) {
  std::ostringstream out;
  out << "(" << x[0];
  for (int d = 1; d < D; ++d) out << ", " << x[d];
  out << ")";
  return out.str();
}

//! Index of the plane all of `ends` lie within `tolerance` of (the nearest), or −1.
template <int D>
int plane_of(const std::vector<Vec<D>>& ends, const std::vector<MirrorPlane>& planes,
             double tolerance) {
  int best = -1;
  double best_distance = tolerance;
  for (std::size_t k = 0; k < planes.size(); ++k) {
    double distance = 0.0;
    for (const auto& x : ends)
      distance = std::max(distance, std::abs(x[planes[k].axis] - planes[k].position));
    if (distance <= best_distance) best_distance = distance, best = static_cast<int>(k);
  }
  return best;
}

double segment_distance2(const Vec2& x, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double s = length2 > 0.0 ? std::clamp((x - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + s * ab - x).squaredNorm();
}

//! Squared distance from x to triangle abc (closest point by the Voronoi regions of the
//! triangle's corners, edges and face).
double triangle_distance2(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ax = x - a;
  const double d1 = ab.dot(ax), d2 = ac.dot(ax);
  if (d1 <= 0.0 && d2 <= 0.0) return ax.squaredNorm();
  const Vec3 bx = x - b;
  const double d3 = ab.dot(bx), d4 = ac.dot(bx);
  if (d3 >= 0.0 && d4 <= d3) return bx.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return (a + d1 / (d1 - d3) * ab - x).squaredNorm();
  const Vec3 cx = x - c;
  const double d5 = ab.dot(cx), d6 = ac.dot(cx);
  if (d6 >= 0.0 && d5 <= d6) return cx.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return (a + d2 / (d2 - d6) * ac - x).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b) - x).squaredNorm();
  const double denominator = 1.0 / (va + vb + vc);
  return (a + ab * (vb * denominator) + ac * (vc * denominator) - x).squaredNorm();
}

}  // namespace

template <int D>
Enclosure<D>::Enclosure(const std::vector<Vec<D>>& x, long begin, long end,
                        const MembraneConnectivity& connectivity,
                        const std::vector<MirrorPlane>& planes, double tolerance) {
  const long n = end - begin;
  // Open ends (2D) or boundary edges (3D), as lists of the points they consist of.
  std::vector<std::vector<Vec<D>>> open;
  if constexpr (D == 2) {
    for (long i = 0; i + 1 < n; ++i)
      pieces_.push_back({{x[begin + i], x[begin + i + 1]}, true, -1});
    if (connectivity.closed_curve && n > 2)
      pieces_.push_back({{x[end - 1], x[begin]}, true, -1});
    else if (n > 0)
      open = {{x[begin]}, {x[end - 1]}};
  } else {
    std::map<std::pair<int, int>, int> edge_use;
    for (const auto& t : connectivity.triangles) {
      pieces_.push_back({{x[begin + t[0]], x[begin + t[1]], x[begin + t[2]]}, true, -1});
      for (int e = 0; e < 3; ++e) {
        const int a = t[e], b = t[(e + 1) % 3];
        ++edge_use[{std::min(a, b), std::max(a, b)}];
      }
    }
    for (const auto& [edge, uses] : edge_use)
      if (uses == 1) open.push_back({x[begin + edge.first], x[begin + edge.second]});
  }
  if (pieces_.empty()) problem_ = "the membrane has no segments or triangles to enclose a region";

  // Join every open end to its mirror image in the plane it lies on.
  std::vector<int> plane_used(planes.size(), -1);
  for (const auto& ends : open) {
    const int k = plane_of<D>(ends, planes, tolerance);
    if (k < 0) {
      if (problem_.empty())
        problem_ = "the membrane is open at " + where<D>(ends.front()) +
                   " and that end is not on a wall or symmetry face of the grid";
      continue;
    }
    if (plane_used[k] < 0) {
      plane_used[k] = static_cast<int>(used_.size());
      used_.push_back(planes[k]);
    }
    const int tag = plane_used[k];
    if constexpr (D == 2) {
      pieces_.push_back({{ends[0], reflect<D>(ends[0], planes[k])}, false, tag});
    } else {
      const Vec3 a = ends[0], b = ends[1], a2 = reflect<D>(a, planes[k]),
                 b2 = reflect<D>(b, planes[k]);
      pieces_.push_back({{a, b, b2}, false, tag});
      pieces_.push_back({{a, b2, a2}, false, tag});
    }
  }
  for (std::size_t k = 0; k < used_.size(); ++k) mirror(used_[k], static_cast<int>(k));
  index_pieces();
}

template <int D>
void Enclosure<D>::mirror(const MirrorPlane& plane, int index) {
  const std::size_t count = pieces_.size();
  for (std::size_t i = 0; i < count; ++i) {
    if (!pieces_[i].membrane && pieces_[i].plane == index) continue;  // lies in the plane
    Piece image = pieces_[i];
    for (auto& corner : image.corner) corner = reflect<D>(corner, plane);
    pieces_.push_back(image);
  }
}

template <int D>
void Enclosure<D>::index_pieces() {
  if (pieces_.empty()) return;
  bounds_.lower = bounds_.upper = pieces_.front().corner[0];
  double longest = 0.0;
  for (const auto& piece : pieces_)
    for (int i = 0; i < D; ++i) {
      bounds_.lower = bounds_.lower.cwiseMin(piece.corner[i]);
      bounds_.upper = bounds_.upper.cwiseMax(piece.corner[i]);
      if (piece.membrane)
        longest = std::max(longest, (piece.corner[i] - piece.corner[(i + 1) % D]).norm());
    }
  // Buckets about a piece wide, at most 64 per axis.
  const Vec<D> extent = bounds_.upper - bounds_.lower;
  bucket_size_ = std::max({longest, extent.maxCoeff() / 64.0, 1e-300});
  origin_ = bounds_.lower;
  for (int d = 0; d < D; ++d)
    buckets_[d] = std::max(1, static_cast<int>(std::ceil(extent[d] / bucket_size_)) + 1);
  long cells = 1, rows = 1;
  for (int d = 0; d < D; ++d) cells *= buckets_[d];
  for (int d = 1; d < D; ++d) rows *= buckets_[d];
  cell_pieces_.assign(cells, {});
  row_pieces_.assign(rows, {});
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    Vec<D> lo = pieces_[i].corner[0], hi = lo;
    for (const auto& corner : pieces_[i].corner) lo = lo.cwiseMin(corner), hi = hi.cwiseMax(corner);
    IVec<D> a, b;
    for (int d = 0; d < D; ++d) {
      a[d] = static_cast<int>(std::floor((lo[d] - origin_[d]) / bucket_size_));
      b[d] = std::min(buckets_[d] - 1,
                      static_cast<int>(std::floor((hi[d] - origin_[d]) / bucket_size_)));
    }
    const int piece = static_cast<int>(i);
    if constexpr (D == 2) {
      for (int y = a[1]; y <= b[1]; ++y) {
        row_pieces_[y].push_back(piece);
        if (pieces_[i].membrane)
          for (int x = a[0]; x <= b[0]; ++x) cell_pieces_[x + buckets_[0] * y].push_back(piece);
      }
    } else {
      for (int z = a[2]; z <= b[2]; ++z)
        for (int y = a[1]; y <= b[1]; ++y) {
          row_pieces_[y + buckets_[1] * z].push_back(piece);
          if (pieces_[i].membrane)
            for (int x = a[0]; x <= b[0]; ++x)
              cell_pieces_[x + buckets_[0] * (y + buckets_[1] * z)].push_back(piece);
        }
    }
  }
}

template <int D>
bool Enclosure<D>::inside(const Vec<D>& x) const {
  for (int d = 0; d < D; ++d)
    if (!(x[d] >= bounds_.lower[d] && x[d] <= bounds_.upper[d])) return false;
  long row = 0;
  for (int d = D - 1; d >= 1; --d)
    row = row * buckets_[d] +
          std::min(buckets_[d] - 1, static_cast<int>((x[d] - origin_[d]) / bucket_size_));
  int crossings = 0;
  if constexpr (D == 2) {
    // Half-open rule: a segment counts when it has one end above y and one at or below it,
    // so a ray through a shared corner counts it once.
    for (int i : row_pieces_[row]) {
      const Vec2 &a = pieces_[i].corner[0], &b = pieces_[i].corner[1];
      if ((a.y() > x.y()) == (b.y() > x.y())) continue;
      const double at = a.x() + (x.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (at > x.x()) ++crossings;
    }
  } else {
    // The ray starts a hair off the lattice lines (an irrational fraction of a bucket), so it
    // misses the edges and corners the triangles share.
    const double y = x.y() + 0.61803398875e-9 * bucket_size_;
    const double z = x.z() + 0.41421356237e-9 * bucket_size_;
    for (int i : row_pieces_[row]) {
      const Vec3 &a = pieces_[i].corner[0], &b = pieces_[i].corner[1], &c = pieces_[i].corner[2];
      const double area = (b.y() - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (b.z() - a.z());
      if (area == 0.0) continue;  // seen edge-on from the ray
      const double u = ((y - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (z - a.z())) / area;
      const double v = ((b.y() - a.y()) * (z - a.z()) - (y - a.y()) * (b.z() - a.z())) / area;
      if (u < 0.0 || v < 0.0 || u + v > 1.0) continue;
      if (a.x() + u * (b.x() - a.x()) + v * (c.x() - a.x()) > x.x()) ++crossings;
    }
  }
  return crossings % 2 == 1;
}

template <int D>
double Enclosure<D>::distance(const Vec<D>& x, double limit) const {
  // Search rings of buckets outwards until the nearest piece found is closer than the ring.
  IVec<D> home;
  for (int d = 0; d < D; ++d)
    home[d] = static_cast<int>(std::floor((x[d] - origin_[d]) / bucket_size_));
  double best2 = std::numeric_limits<double>::infinity();
  const int rings = buckets_.maxCoeff() + 1;
  for (int ring = 0; ring <= rings; ++ring) {
    IVec<D> lo, hi;
    for (int d = 0; d < D; ++d) {
      lo[d] = std::max(0, home[d] - ring);
      hi[d] = std::min(buckets_[d] - 1, home[d] + ring);
    }
    auto visit = [&](const IVec<D>& cell) {
      long index = 0;
      for (int d = D - 1; d >= 0; --d) index = index * buckets_[d] + cell[d];
      for (int i : cell_pieces_[index]) {
        const auto& c = pieces_[i].corner;
        if constexpr (D == 2)
          best2 = std::min(best2, segment_distance2(x, c[0], c[1]));
        else
          best2 = std::min(best2, triangle_distance2(x, c[0], c[1], c[2]));
      }
    };
    IVec<D> cell = lo;
    while ((lo.array() <= hi.array()).all()) {  // every bucket of [lo, hi] on the ring
      bool on_ring = false;
      for (int d = 0; d < D; ++d)
        on_ring = on_ring || cell[d] == home[d] - ring || cell[d] == home[d] + ring;
      if (on_ring) visit(cell);
      int d = 0;
      while (d < D && ++cell[d] > hi[d]) cell[d] = lo[d], ++d;
      if (d == D) break;
    }
    if (best2 <= std::pow(ring * bucket_size_, 2) || ring * bucket_size_ >= limit) break;
  }
  return std::sqrt(best2);
}

namespace {

template <int D>
class EnclosedRegion final : public Region<D> {
 public:
  EnclosedRegion(std::shared_ptr<const Enclosure<D>> enclosure, double gap)
      : enclosure_(std::move(enclosure)), gap_(gap) {}
  bool contains(const Vec<D>& x) const override {
    return enclosure_->inside(x) && (gap_ <= 0.0 || enclosure_->distance(x, gap_) >= gap_);
  }
  Box<D> bounds() const override { return enclosure_->bounds(); }

 private:
  std::shared_ptr<const Enclosure<D>> enclosure_;
  double gap_;
};

}  // namespace

template <int D>
RegionPtr<D> make_enclosed_region(std::shared_ptr<const Enclosure<D>> enclosure, double gap) {
  return std::make_unique<EnclosedRegion<D>>(std::move(enclosure), gap);
}

template class Enclosure<2>;
template class Enclosure<3>;
template RegionPtr<2> make_enclosed_region<2>(std::shared_ptr<const Enclosure<2>>, double);
template RegionPtr<3> make_enclosed_region<3>(std::shared_ptr<const Enclosure<3>>, double);

}  // namespace pellicle
