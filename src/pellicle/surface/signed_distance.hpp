#pragma once
//! The signed distance DC_i from a point to another surface given only by points (Suchde &
//! Kuhnert §3.6, eq 10): a local quadratic d(x) fitted by least squares to d(x_m) = 0 and
//! d(x_m ± ξ n_m) = ±ξ at the other surface's points m near x, evaluated at x. The paper
//! leaves the local coordinates of eq 10 open; here they are a frame (u, v, w) with w along
//! the mean normal of the points m and its origin at the nearest of them, and
//!   d = d0 + d1 u + d2 v + d3 u² + d4 v² + d5 u v + d6 w      (3D)
//!   d = d0 + d1 u + d3 u² + d6 w                              (2D)
//! quadratic along the surface and linear across it, so that the ±ξ conditions fix d6 and
//! d = 0 is the quadratic graph the points lie on (docs/theory/surface-contact.md).

#include "pellicle/core/types.hpp"

namespace pellicle {

template <int D>
struct SignedDistance {
  double distance = 0.0;              //!< d(x)/|∇d(x)|: DC_i, positive on the normals' side
  Vec<D> direction = Vec<D>::Zero();  //!< ∇d/|∇d| at x: the way to the positive side
  bool valid = false;                 //!< false when the fit has no gradient at x
};

//! DC at x from the `count` points `points` with unit normals `normals` (oriented alike;
//! points[0] the nearest to x), with offset ξ = `xi` > 0. Fewer points than the quadratic
//! terms need (6 in 3D, 3 in 2D) give the plane (line) d = d0 + d1 u (+ d2 v) + d6 w; a
//! single point gives the plane through it normal to its normal.
template <int D>
SignedDistance<D> signed_distance(const Vec<D>& x, const Vec<D>* points, const Vec<D>* normals,
                                  int count, double xi);

}  // namespace pellicle
