#pragma once
//! Where point management puts a point it creates (Suchde & Kuhnert §3.4–3.5): the
//! curvature-corrected position of eqs 6–9 for points in holes and for merged interior
//! points, a parabola along the boundary for boundary points, and the checks that a place is
//! free. Header-only: small functions called once per candidate from the parallel loops.

#include <algorithm>
#include <vector>

#include "pellicle/pointcloud/neighbour_search.hpp"
#include "pellicle/surface/frames.hpp"
#include "pellicle/surface/point_cloud.hpp"

namespace pellicle {

//! eq 6: the mean of the normals of the `count` points of a triangle (a segment on a curve,
//! a merged pair), not normalised.
template <int D>
Vec<D> approximate_normal(const PointCloud<D>& cloud, const int* points, int count) {
  Vec<D> n = Vec<D>::Zero();
  for (int k = 0; k < count; ++k) n += cloud.normal(points[k]);
  return n / count;
}

//! eqs 7–9: x_new = x_c + step d_κ n_approx with d_κ = Σ_j ω_j (x_j − x_c)·n_j /
//! Σ_j ω_j n_approx·n_j, the place where the vectors to the points are tangential on average,
//! Σ_j ω_j (x_j − x_new)·n_j = 0 (eq 8). The paper's rule is ω_j = 1 and step = 1; `weights`
//! (null for ω_j = 1) and `step` give the variant of docs/theory/surface-management.md.
//! Returns x_c when the normals disagree (Σ_j ω_j n_approx·n_j ≤ 0). The move is at most the
//! simplex's size (the largest |x_j − x_c|): on a smooth surface it is κ r²/2, far below it;
//! across a crease (two sheets pressed flat by contact meet the rest of their spheres) eq 8
//! can put the point far off the surface.
template <int D>
Vec<D> curvature_corrected(const PointCloud<D>& cloud, const int* points, const double* weights,
                           int count, const Vec<D>& x_c, const Vec<D>& n_approx, double step) {
  double along = 0.0, across = 0.0, size = 0.0;
  for (int k = 0; k < count; ++k) {
    const Vec<D> n = cloud.normal(points[k]);
    const double w = weights ? weights[k] : 1.0;
    along += w * (cloud.position[points[k]] - x_c).dot(n);
    across += w * n_approx.dot(n);
    size = std::max(size, (cloud.position[points[k]] - x_c).norm());
  }
  if (!(across > 0.0)) return x_c;
  const Vec<D> move = step * along / across * n_approx;
  const double length = move.norm();
  return length > size ? Vec<D>(x_c + (size / length) * move) : Vec<D>(x_c + move);
}

//! True when no point of `cloud` other than `except[0 … count)` lies closer than `radius` to
//! x. `search` must hold the cloud as it is now.
template <int D>
bool nothing_within(const PointCloud<D>& cloud, const NeighbourSearch<D>& search, const Vec<D>& x,
                    double radius, const int* except, int count) {
  thread_local std::vector<int> found;
  search.around(cloud, x, radius, found);
  for (int j : found) {
    bool listed = false;
    for (int k = 0; k < count; ++k) listed = listed || j == except[k];
    if (!listed && (cloud.position[j] - x).squaredNorm() < radius * radius) return false;
  }
  return true;
}

//! The point halfway between boundary points a and b on the boundary curve: a parabola
//! y(s) = C s (s − L) through a (s = 0) and b (s = L) across the chord, its C fitted by
//! weighted least squares to the other boundary points within h of the chord's midpoint
//! that lie along the chord (|y| ≤ |s − L/2|), evaluated at s = L/2. The chord's midpoint
//! when there are none.
template <int D>
Vec<D> boundary_midpoint(const PointCloud<D>& cloud, const NeighbourSearch<D>& search, int a, int b,
                         double weight_exponent) {
  const Vec<D> xa = cloud.position[a];
  const Vec<D> chord = cloud.position[b] - xa;
  const double length = chord.norm();
  const Vec<D> e = chord / length, mid = xa + 0.5 * chord;
  const double h = 0.5 * (cloud.smoothing_length[a] + cloud.smoothing_length[b]);
  thread_local std::vector<int> found;
  search.around(cloud, mid, h, found);
  Vec<D> yq = Vec<D>::Zero();
  double qq = 0.0;
  for (int j : found) {
    if (!cloud.boundary[j] || j == a || j == b) continue;
    const Vec<D> d = cloud.position[j] - xa;
    const double s = e.dot(d);
    const Vec<D> y = d - s * e;
    if (y.norm() > std::abs(s - 0.5 * length)) continue;  // across, not along the boundary
    const double q = s * (s - length);
    const double w = gaussian_weight((cloud.position[j] - mid).squaredNorm(), h, weight_exponent);
    yq += w * q * y;
    qq += w * q * q;
  }
  if (!(qq > 0.0)) return mid;
  return mid - 0.25 * length * length / qq * yq;
}

//! ν of a new boundary point between boundary points with normals ν_a, ν_b: their mean,
//! made normal to the new point's manifold normal n.
template <int D>
Vec<D> boundary_normal_between(const Vec<D>& nu_a, const Vec<D>& nu_b, const Vec<D>& n) {
  Vec<D> nu = nu_a + nu_b;
  nu -= nu.dot(n) * n;
  const double length = nu.norm();
  return length > 0.0 ? Vec<D>(nu / length) : Vec<D>::Zero();
}

//! A frame with unit normal n: the first tangent continues `start`'s (or is `hint` projected
//! into the tangent plane when `hint` is not zero, as for ν at boundary points).
template <int D>
Mat<D> frame_with_normal(const Mat<D>& start, const Vec<D>& n, const Vec<D>& hint) {
  Mat<D> f = start;
  if (hint.squaredNorm() > 0.0) f.col(0) = hint;
  set_normal<D>(f, n);
  return f;
}

}  // namespace pellicle
