#include <Eigen/Geometry>

#include <algorithm>

#include "pellicle/normals/frame_estimator.hpp"
#include "pellicle/pointcloud/cell_groups.hpp"
#include "pellicle/pointcloud/local_frame.hpp"
#include "pellicle/pointcloud/orientation_sweep.hpp"

namespace pellicle {

namespace {

//! Flip normals of points [begin, end) that are not fixed so that neighbouring points (within
//! a cell of each other) agree, walking outwards from the fixed points, then from the first
//! point of each connected piece that has none.
template <int D>
void propagate(const std::vector<Vec<D>>& x, long begin, long end, const std::vector<bool>& fixed,
               std::vector<Vec<D>>& normal, double cell) {
  const CellGroups<D> groups(x, begin, end, Vec<D>::Zero(), cell);
  std::vector<long> settled;  // their neighbours follow them first
  for (long p = begin; p < end; ++p)
    if (fixed[p - begin]) settled.push_back(p);
  auto within_a_cell = [&](long p, auto&& visit) {
    groups.for_each_around(groups.cell_of(x[p]), [&](int g) {
      for (const long* q = groups.begin(g); q != groups.end(g); ++q)
        if ((x[*q] - x[p]).squaredNorm() <= cell * cell) visit(*q);
    });
  };
  orientation_sweep(
      begin, end, settled, within_a_cell,
      [&](long from, long to) {
        if (normal[to].dot(normal[from]) < 0.0) normal[to] = -normal[to];
      },
      [](const std::vector<long>&) {});
}

}  // namespace

template <int D>
std::vector<int> sides_from_inside(const std::vector<Vec<D>>& x, long begin, long end,
                                   const std::vector<Vec<D>>& normal,
                                   const std::vector<Vec<D>>& inside, double cell) {
  std::vector<int> side(end - begin, 0);
  if (inside.empty()) return side;
  const CellGroups<D> groups(inside, 0, static_cast<long>(inside.size()), Vec<D>::Zero(), cell);
  for (long p = begin; p < end; ++p) {
    Vec<D> sum = Vec<D>::Zero();
    long count = 0;
    groups.for_each_around(groups.cell_of(x[p]), [&](int g) {
      for (const long* q = groups.begin(g); q != groups.end(g); ++q)
        if ((inside[*q] - x[p]).squaredNorm() <= cell * cell) sum += inside[*q], ++count;
    });
    if (count == 0) continue;
    const double facing = normal[p].dot(x[p] - sum / static_cast<double>(count));
    side[p - begin] = facing > 0.0 ? 1 : facing < 0.0 ? -1 : 0;
  }
  return side;
}

template <int D>
void complete_frames(const std::vector<Vec<D>>& x, long begin, long end,
                     const FrameOrientation<D>& orientation, const std::vector<Vec<D>>& previous,
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
    if (orientation.rule == NormalOrientation::away_from_inside) {
      const auto side = sides_from_inside<D>(x, begin, end, normal, orientation.inside, cell);
      for (long p = begin; p < end; ++p) {
        if (fixed[p - begin] || side[p - begin] == 0) continue;
        if (side[p - begin] < 0) normal[p] = -normal[p];
        fixed[p - begin] = true;  // settled here; the rest follow their neighbours
      }
      propagate<D>(x, begin, end, fixed, normal, cell);
    } else if (orientation.rule == NormalOrientation::outward) {
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

template void complete_frames<2>(const std::vector<Vec2>&, long, long, const FrameOrientation<2>&,
                                 const std::vector<Vec2>&, std::vector<Vec2>&, std::vector<Vec2>&,
                                 double);
template void complete_frames<3>(const std::vector<Vec3>&, long, long, const FrameOrientation<3>&,
                                 const std::vector<Vec3>&, std::vector<Vec3>&, std::vector<Vec3>&,
                                 double);
template <int D>
WithinACell<D>::WithinACell(const std::vector<Vec<D>>& position, long begin, long end, double cell)
    : points_(position.begin() + begin, position.begin() + end),
      cell_(cell),
      groups_(points_, 0, end - begin, Vec<D>::Zero(), cell) {}

template <int D>
bool WithinACell<D>::operator()(const Vec<D>& y) const {
  // The test of sides_from_inside, |y − x|² ≤ cell², from the other side.
  bool close = false;
  groups_.for_each_around(groups_.cell_of(y), [&](int g) {
    for (const long* q = groups_.begin(g); q != groups_.end(g) && !close; ++q)
      close = (points_[*q] - y).squaredNorm() <= cell_ * cell_;
  });
  return close;
}

template class WithinACell<2>;
template class WithinACell<3>;
template std::vector<int> sides_from_inside<2>(const std::vector<Vec2>&, long, long,
                                               const std::vector<Vec2>&, const std::vector<Vec2>&,
                                               double);
template std::vector<int> sides_from_inside<3>(const std::vector<Vec3>&, long, long,
                                               const std::vector<Vec3>&, const std::vector<Vec3>&,
                                               double);

}  // namespace pellicle
