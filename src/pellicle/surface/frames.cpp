#include "pellicle/surface/frames.hpp"

#include <Eigen/Eigenvalues>

#include "pellicle/core/error.hpp"
#include "pellicle/core/loop_failure.hpp"
#include "pellicle/pointcloud/orientation_sweep.hpp"
#include "pellicle/pointcloud/weighted_moments.hpp"

namespace pellicle {

namespace {

//! The eq 4 matrix Σ W d dᵀ/|d|² over the neighbours of i (only boundary ones if asked).
template <int D>
Mat<D> direction_matrix(const PointCloud<D>& cloud, const NeighbourLists& nb, std::size_t i,
                        double c, bool boundary_only, int& used) {
  WeightedMoments<D, false> m;
  used = 0;
  const Vec<D>& x = cloud.position[i];
  const double h = cloud.smoothing_length[i];
  for (long k = nb.begin(i) + 1; k < nb.end(i); ++k) {
    const int j = nb.index[k];
    if (boundary_only && !cloud.boundary[j]) continue;
    const Vec<D> d = cloud.position[j] - x;
    const double r2 = d.squaredNorm();
    if (r2 == 0.0) continue;
    m.add(d, gaussian_weight(r2, h, c) / r2);
    ++used;
  }
  return m.matrix();
}

//! Boundary neighbours whose second spread is above this share of the first lie along two
//! directions: the point is a corner of the boundary.
constexpr double kCornerSpread = 0.3;

[[noreturn]] void too_few(std::size_t i, int found) {
  throw NumericalError({0.0, 0, "surface", static_cast<long>(i)},
                       "point " + std::to_string(i) + " has " + std::to_string(found) +
                           " neighbours within its smoothing length, too few to define its "
                           "normal: the cloud has a hole there (raise h or refine the cloud)");
}

}  // namespace

template <int D>
void estimate_frames(PointCloud<D>& cloud, const NeighbourLists& nb, const FrameOptions& options,
                     bool keep_side) {
  const long n = static_cast<long>(cloud.size());
  const double c = options.weight_exponent;
  LoopFailure failure;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    int used = 0;
    const Mat<D> m = direction_matrix(cloud, nb, i, c, false, used);
    if (used < D - 1 + (D == 3)) {
      failure.record(i, used);
      continue;
    }
    const Mat<D> old = cloud.frame[i];
    Vec<D> normal;
    Vec<D> boundary_normal = Vec<D>::Zero();
    const Vec<D> x = cloud.position[i];
    bool done = false;
    bool at_corner = false;
    if constexpr (D == 3) {
      int boundary_used = 0;
      const Mat3 mb =
          cloud.boundary[i] ? direction_matrix(cloud, nb, i, c, true, boundary_used) : Mat3::Zero();
      Eigen::SelfAdjointEigenSolver<Mat3> along(mb);
      const Vec3 spread = along.eigenvalues();
      if (boundary_used > 0 && spread[1] < kCornerSpread * spread[2]) {
        // §3.2 at the boundary: the boundary tangent from the boundary neighbours (their
        // main direction), the normal minimising eq 4 among directions orthogonal to it.
        const Vec3 tb = along.eigenvectors().col(2);
        Eigen::Matrix<double, 3, 2> plane;
        plane.col(0) = tangent_in_plane(tb, old.col(0));
        plane.col(1) = tb.cross(plane.col(0));
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> in_plane(plane.transpose() * m * plane);
        normal = (plane * in_plane.eigenvectors().col(0)).normalized();
        boundary_normal = tb.cross(normal);
        done = true;
      }
    }
    if (!done) {
      normal = least_spread_direction<D>(m);
      if constexpr (D == 2) {
        if (cloud.boundary[i]) boundary_normal = Vec2(normal.y(), -normal.x());
      } else if (cloud.boundary[i]) {
        // A corner: the boundary neighbours spread in two directions and have no main one.
        // ν is then the direction away from the neighbours within the tangent plane.
        Vec3 inward = Vec3::Zero();
        for (long k = nb.begin(i) + 1; k < nb.end(i); ++k)
          inward += cloud.position[nb.index[k]] - x;
        inward -= inward.dot(normal) * normal;
        boundary_normal = -inward.normalized();
        at_corner = true;
      }
    }
    if (keep_side && normal.dot(old.col(D - 1)) < 0.0) normal = -normal;  // eq 5
    if (cloud.boundary[i]) {
      // ν points out of the manifold: away from the neighbours.
      Vec<D> towards = Vec<D>::Zero();
      for (long k = nb.begin(i) + 1; k < nb.end(i); ++k) towards += cloud.position[nb.index[k]] - x;
      if (boundary_normal.dot(towards) > 0.0) boundary_normal = -boundary_normal;
      cloud.boundary_normal[i] = boundary_normal;
      cloud.corner[i] = at_corner ? 1 : 0;
    }
    Vec<D> hint = old.col(0);
    if (cloud.boundary[i] && D == 3) hint = boundary_normal;
    cloud.frame[i] = frame_from<D>(normal, hint);
  }
  if (failure.failed()) too_few(failure.index(), failure.detail());
}

template <int D>
void orient_consistently(PointCloud<D>& cloud, const NeighbourLists& nb,
                         const std::vector<Vec<D>>* reference) {
  orientation_sweep(
      0, static_cast<long>(cloud.size()), {},
      [&](long i, auto&& visit) {
        for (long k = nb.begin(i) + 1; k < nb.end(i); ++k) visit(nb.index[k]);
      },
      [&](long from, long to) {
        if (cloud.normal(to).dot(cloud.normal(from)) < 0.0) flip_normal<D>(cloud.frame[to]);
      },
      [&](const std::vector<long>& piece) {
        // One sign for the whole piece: along the reference normals, else outward.
        double agreement = 0.0;
        Vec<D> centroid = Vec<D>::Zero();
        for (long i : piece) centroid += cloud.position[i];
        centroid /= static_cast<double>(piece.size());
        for (long i : piece)
          agreement += reference ? cloud.normal(i).dot((*reference)[i])
                                 : cloud.normal(i).dot(cloud.position[i] - centroid);
        if (agreement < 0.0)
          for (long i : piece) flip_normal<D>(cloud.frame[i]);
      });
}

template void estimate_frames<2>(PointCloud<2>&, const NeighbourLists&, const FrameOptions&, bool);
template void estimate_frames<3>(PointCloud<3>&, const NeighbourLists&, const FrameOptions&, bool);
template void orient_consistently<2>(PointCloud<2>&, const NeighbourLists&,
                                     const std::vector<Vec2>*);
template void orient_consistently<3>(PointCloud<3>&, const NeighbourLists&,
                                     const std::vector<Vec3>*);

}  // namespace pellicle
