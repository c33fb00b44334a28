// Triangulated surfaces (STL or OBJ files): closest points on the triangles found through a
// k-d tree of triangle centroids (nanoflann), normals of the nearest triangle, boundary along
// the edges that only one triangle uses.
#include <Eigen/Geometry>
#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "pellicle/geometry/shape_support.hpp"
#include "pellicle/geometry/surface_shapes.hpp"

namespace pellicle {
namespace {

//! The point of triangle abc nearest to p (Ericson, Real-Time Collision Detection §5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

//! Triangle centroids as nanoflann's dataset.
struct Centroids {
  std::vector<Vec3> points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t d) const { return points[i][d]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};
using CentroidTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Centroids>, Centroids,
                                        3>;

//! Chains of boundary edges (used by one triangle only), split at sharp corners (turning by
//! more than 30°) and where more than two boundary edges meet; closed loops without such a
//! vertex stay closed. Each chain lists its vertices, a closed one repeating its first.
std::vector<std::pair<std::vector<Vec3>, bool>> boundary_chains(const SurfaceMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  std::map<int, std::vector<int>> next;
  for (const auto& [edge, count] : uses)
    if (count == 1) {
      next[edge.first].push_back(edge.second);
      next[edge.second].push_back(edge.first);
    }
  auto is_break = [&](int v) {
    const auto& n = next.at(v);
    if (n.size() != 2) return true;
    const Vec3 in = (mesh.vertices[v] - mesh.vertices[n[0]]).normalized();
    const Vec3 out = (mesh.vertices[n[1]] - mesh.vertices[v]).normalized();
    return in.dot(out) < std::cos(std::numbers::pi / 6.0);
  };
  std::map<std::pair<int, int>, bool> walked;
  std::vector<std::pair<std::vector<Vec3>, bool>> chains;
  auto walk = [&](int from, int to) {
    std::vector<int> chain{from};
    int previous = from, current = to;
    walked[std::minmax(from, to)] = true;
    while (true) {
      chain.push_back(current);
      if (current == from || is_break(current)) break;
      const auto& n = next.at(current);
      const int ahead = n[0] == previous ? n[1] : n[0];
      if (walked[std::minmax(current, ahead)]) break;
      walked[std::minmax(current, ahead)] = true;
      previous = current, current = ahead;
    }
    std::vector<Vec3> points;
    for (int v : chain) points.push_back(mesh.vertices[v]);
    chains.push_back({points, chain.front() == chain.back()});
  };
  for (const auto& [v, n] : next)
    if (is_break(v))
      for (int w : n)
        if (!walked[std::minmax(v, w)]) walk(v, w);
  for (const auto& [v, n] : next)
    for (int w : n)
      if (!walked[std::minmax(v, w)]) walk(v, w);
  return chains;
}

class MeshShape final : public SurfaceShape<3> {
 public:
  MeshShape(SurfaceMesh mesh, std::string name) : name_(std::move(name)) {
    for (const auto& t : mesh.triangles) {
      const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
      const Vec3 n = (b - a).cross(c - a);
      if (n.norm() == 0.0) continue;  // degenerate: no area, no normal
      triangles_.push_back({a, b, c});
      normals_.push_back(n.normalized());
      const Vec3 centroid = (a + b + c) / 3.0;
      centroids_.points.push_back(centroid);
      for (const Vec3* v : {&a, &b, &c}) reach_ = std::max(reach_, (*v - centroid).norm());
    }
    chains_ = boundary_chains(mesh);
    tree_ =
        std::make_unique<CentroidTree>(3, centroids_, nanoflann::KDTreeSingleIndexAdaptorParams(8));
  }

  std::string describe() const override {
    return "mesh of " + std::to_string(triangles_.size()) + " triangles from " + name_;
  }

  Vec3 project(const Vec3& x) const override { return triangles_.empty() ? x : nearest(x).first; }

  //! The normal of the nearest triangle (its corners counter-clockwise seen from the side
  //! it points to).
  Vec3 normal(const Vec3& x) const override {
    return triangles_.empty() ? Vec3(Vec3::UnitZ()) : normals_[nearest(x).second];
  }

  double surface_error(const Vec3& x) const override { return (x - project(x)).norm(); }

  double measure() const override { return carrier_measure<3>(triangles_); }

  PointSample<3> sample(const SamplingOptions& options) const override {
    SampleRandom random(options.seed);
    std::vector<Vec3> boundary;
    for (const auto& [points, closed] : chains_) {
      const int pieces = static_cast<int>(points.size()) - 1;
      const std::vector<Vec3>* p = &points;
      BoundaryCurve<3> curve{[p, pieces](double u) {
                               const int k = std::min(pieces - 1, static_cast<int>(u * pieces));
                               const double w = u * pieces - k;
                               return Vec3((1.0 - w) * (*p)[k] + w * (*p)[k + 1]);
                             },
                             closed, pieces};
      for (const Vec3& x : boundary_points<3>(curve, options.spacing, random))
        boundary.push_back(x);
    }
    // Candidates are drawn on the triangles themselves: no projection needed.
    return select_spaced<3>(
        *this, boundary,
        carrier_candidates<3>(triangles_, nullptr, kCandidateCell * options.spacing, random),
        options.spacing, random);
  }

 private:
  //! Nearest point on the mesh and its triangle: no triangle whose centroid is farther than
  //! the best distance so far plus the largest centroid-to-corner distance can be nearer.
  std::pair<Vec3, std::size_t> nearest(const Vec3& x) const {
    std::uint32_t first = 0;
    double d2 = 0.0;
    tree_->knnSearch(x.data(), 1, &first, &d2);
    Vec3 best =
        closest_on_triangle(x, triangles_[first][0], triangles_[first][1], triangles_[first][2]);
    std::size_t which = first;
    double distance = (best - x).norm();
    const double radius = distance + reach_;
    std::vector<std::pair<std::uint32_t, double>> near;
    tree_->radiusSearch(x.data(), radius * radius, near, nanoflann::SearchParams(32, 0, false));
    for (const auto& [t, unused] : near) {
      const Vec3 p = closest_on_triangle(x, triangles_[t][0], triangles_[t][1], triangles_[t][2]);
      if ((p - x).norm() < distance) distance = (p - x).norm(), best = p, which = t;
    }
    return {best, which};
  }

  std::string name_;
  std::vector<Simplex<3>> triangles_;
  std::vector<Vec3> normals_;
  std::vector<std::pair<std::vector<Vec3>, bool>> chains_;
  Centroids centroids_;
  double reach_ = 0.0;
  std::unique_ptr<CentroidTree> tree_;
};

}  // namespace

SurfaceShapePtr<3> make_mesh_shape(SurfaceMesh mesh, std::string name) {
  return std::make_unique<MeshShape>(std::move(mesh), std::move(name));
}

}  // namespace pellicle
