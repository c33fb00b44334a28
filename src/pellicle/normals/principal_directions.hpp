#pragma once
//! Principal directions of a membrane's points at the scale of their spacing. The normal at a
//! point is the direction of least spread of its neighbours within a radius r, weighted by
//! (1 − (d/r)²)², about their weighted mean (pointcloud/weighted_moments.hpp, the moments
//! the surfaces' eq 4 normals also take). The radius follows the points: three times
//! their median nearest-neighbour distance, at most 1.5 cells. At that scale the frames
//! follow the membrane from point to point, as the connectivity estimator's x_{p+1} − x_{p−1}
//! does; a radius of a cell or more averages over the folds a slack membrane forms, and the
//! membrane's strain, taken along those averaged tangents, drifts (docs/validation, normal
//! methods on gas-filled membranes).

#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/pointcloud/cell_groups.hpp"

namespace pellicle {

template <int D>
class PrincipalDirections {
 public:
  //! Neighbourhoods among all of `cloud` (a body's points, with any mirror images).
  PrincipalDirections(const std::vector<Vec<D>>& cloud, double cell);
  double radius() const { return radius_; }
  //! Unit direction of least spread of the neighbours of cloud[p] (unsigned).
  Vec<D> least_spread(long p) const;

 private:
  const std::vector<Vec<D>>& cloud_;
  double radius_;
  CellGroups<D> groups_;
};

//! Median distance from a point of `x` to its nearest other point, among points with one
//! within `search`; `search` when none has.
template <int D>
double median_spacing(const std::vector<Vec<D>>& x, double search);

extern template class PrincipalDirections<2>;
extern template class PrincipalDirections<3>;

}  // namespace pellicle
