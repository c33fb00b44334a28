#include <Eigen/Geometry>

#include <algorithm>
#include <deque>

#include "pellicle/normals/cell_groups.hpp"
#include "pellicle/normals/frame_estimator.hpp"

namespace pellicle {

namespace {

//! Flip normals of points [begin, end) that have no previous normal so that neighbouring
//! points (within a cell of each other) agree, walking outwards from the first point of each
//! connected piece.
template <int D>
void propagate(const std::vector<Vec<D>>& x, long begin, long end, const std::vector<bool>& fixed,
               std::vector<Vec<D>>& normal, double cell) {
  const CellGroups<D> groups(x, begin, end, Vec<D>::Zero(), cell);
  std::vector<char> visited(end - begin, 0);
  std::deque<long> queue;
  for (long start = begin; start < end; ++start) {
    if (visited[start - begin] || fixed[start - begin]) continue;
    visited[start - begin] = 1;
    queue.push_back(start);
    while (!queue.empty()) {
      const long p = queue.front();
      queue.pop_front();
      IVec<D> c;
      for (int d = 0; d < D; ++d) c[d] = static_cast<int>(std::floor(x[p][d] / cell));
      groups.for_each_around(c, [&](int g) {
        for (const long* q = groups.begin(g); q != groups.end(g); ++q) {
          if (visited[*q - begin] || fixed[*q - begin]) continue;
          if ((x[*q] - x[p]).squaredNorm() > cell * cell) continue;
          if (normal[*q].dot(normal[p]) < 0.0) normal[*q] = -normal[*q];
          visited[*q - begin] = 1;
          queue.push_back(*q);
        }
      });
    }
  }
}

}  // namespace

template <int D>
void complete_frames(const std::vector<Vec<D>>& x, long begin, long end,
                     NormalOrientation orientation, const std::vector<Vec<D>>& previous,
                     std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent, double cell) {
  std::vector<bool> fixed(end - begin, false);
  bool any_new = false;
  for (long p = begin; p < end; ++p) {
    if (previous[p].squaredNorm() > 0.0) {  // keep the side it was on
      fixed[p - begin] = true;
      if (normal[p].dot(previous[p]) < 0.0) normal[p] = -normal[p];
    } else {
      any_new = true;
    }
  }
  if (any_new) {
    if (orientation == NormalOrientation::outward) {
      Vec<D> centroid = Vec<D>::Zero();
      for (long p = begin; p < end; ++p) centroid += x[p];
      centroid /= static_cast<double>(end - begin);
      for (long p = begin; p < end; ++p)
        if (!fixed[p - begin] && normal[p].dot(x[p] - centroid) < 0.0) normal[p] = -normal[p];
    } else {
      propagate<D>(x, begin, end, fixed, normal, cell);
    }
  }
  for (long p = begin; p < end; ++p) {
    if constexpr (D == 2) {
      tangent[p] = Vec2(normal[p].y(), -normal[p].x());  // n is t turned +90°
    } else {
      tangent[p] = continue_tangent(tangent[p], normal[p]);
    }
  }
}

template void complete_frames<2>(const std::vector<Vec2>&, long, long, NormalOrientation,
                                 const std::vector<Vec2>&, std::vector<Vec2>&, std::vector<Vec2>&,
                                 double);
template void complete_frames<3>(const std::vector<Vec3>&, long, long, NormalOrientation,
                                 const std::vector<Vec3>&, std::vector<Vec3>&, std::vector<Vec3>&,
                                 double);

}  // namespace pellicle
