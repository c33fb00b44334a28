#pragma once
//! The local 'one-ring' triangulation of a point (Suchde & Kuhnert §3.4, Fig. 1): the
//! neighbours are projected along the normal onto the point's tangent plane, and the one-ring
//! is the set of triangles incident to the point in the Delaunay triangulation of that
//! projected neighbourhood. It is found as the dual of the point's Voronoi cell: the cell is
//! cut out of a square by the bisectors of the neighbours, and two neighbours whose bisectors
//! meet at a corner of the cell form a triangle with the centre. On a curve the 'triangles'
//! are the segments to the nearest neighbour on either side along the tangent. Nothing is
//! stored: the triangulation is built where it is used, independently at every point.

#include <limits>

#include "pellicle/pointcloud/local_fit.hpp"
#include "pellicle/pointcloud/neighbour_search.hpp"
#include "pellicle/surface/point_cloud.hpp"

namespace pellicle {

//! Most neighbours a one-ring takes; a denser neighbourhood keeps its first ones in the
//! neighbour list (the hole filling checks every triangle against the whole cloud).
constexpr int kMaxOneRingNeighbours = 2 * kMaxStencilPoints;
//! Most simplices of one point's one-ring.
constexpr int kMaxOneRing = kMaxOneRingNeighbours;

//! A simplex of the one-ring besides its centre: two neighbours (a triangle with the centre,
//! counter-clockwise about the normal) on a surface, one (a segment) on a curve, where
//! `second` is −1.
struct OneRingSimplex {
  int first = -1;
  int second = -1;
};

//! The one-ring of point i from its neighbour list (self first; the points within `radius`
//! of it) and its frame; writes at most kMaxOneRing simplices to `out` and returns their
//! number.
template <int D>
int one_ring(const PointCloud<D>& cloud, const NeighbourLists& neighbours, std::size_t i,
             double radius, OneRingSimplex* out);

//! The circumcircle of a triangle in space, in the triangle's plane: centre, radius and the
//! barycentric coordinates of the centre (all ≥ 0 when it lies inside the triangle).
//! `radius` is infinite for a degenerate (collinear) triangle.
struct Circumcircle {
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;
  Vec3 barycentric = Vec3::Zero();
  bool inside(double tolerance = 1e-12) const { return barycentric.minCoeff() >= -tolerance; }
};

inline Circumcircle circumcircle(const Vec3& a, const Vec3& b, const Vec3& c) {
  // x_c − a = α u + β v with (x_c − a)·u = |u|²/2 and (x_c − a)·v = |v|²/2.
  const Vec3 u = b - a, v = c - a;
  const double uu = u.squaredNorm(), vv = v.squaredNorm(), uv = u.dot(v);
  const double det = uu * vv - uv * uv;
  Circumcircle cc;
  if (!(det > 1e-14 * uu * vv)) {
    cc.radius = std::numeric_limits<double>::infinity();
    cc.barycentric = Vec3::Constant(-1.0);
    cc.centre = (a + b + c) / 3.0;
    return cc;
  }
  const double alpha = vv * (uu - uv) / (2.0 * det), beta = uu * (vv - uv) / (2.0 * det);
  cc.centre = a + alpha * u + beta * v;
  cc.radius = (cc.centre - a).norm();
  cc.barycentric = Vec3(1.0 - alpha - beta, alpha, beta);
  return cc;
}

}  // namespace pellicle
