#pragma once
//! Point management of a moving cloud (Suchde & Kuhnert §3.4–3.5): holes are filled at the
//! circumcentres of large triangles of each point's local one-ring triangulation (with the
//! curvature correction of eqs 6–9), points closer than r_min h are merged (boundary points
//! kept in place), and every quantity a point carries is interpolated to new and merged
//! points by a second-order moving least-squares fit. Every choice the paper leaves open is
//! written down in docs/theory/surface-management.md.

#include "pellicle/pointcloud/neighbour_search.hpp"
#include "pellicle/surface/frames.hpp"
#include "pellicle/surface/point_cloud.hpp"

namespace pellicle {

//! How the curvature correction places a new point and what normal it gets
//! (docs/theory/surface-management.md, where the two are compared).
enum class CurvatureRule {
  //! The paper's eqs 6–9: n_approx the mean of the normals, x_new where
  //! Σ_j (x_j − x_new)·n_j = 0. On a sphere this lands as far outside as the circumcentre
  //! lies inside.
  tangent_planes,
  //! With the barycentric coordinates λ_j of the circumcentre: n_approx = Σ_j λ_j n_j and
  //! x_new halfway from x_c to where Σ_j λ_j (x_j − x_new)·n_j = 0, which is exact to
  //! leading order on every quadratic surface.
  midway,
};

//! What "no hole of size r_max h" (§2) measures inside a surface: the radius of an empty
//! circle, as §3.4 words the filling ("a circumradius greater than r_max h", default), or
//! its diameter. The paper's clouds have the spacing of equilateral triangles of
//! circumdiameter 0.45 h (0.39 h, 5.9 points per h², 15–20 neighbours as it states), but
//! with the diameter the filling packs an irregular cloud far denser than that (the half
//! pipe went from 2,500 to 5,600 points per unit area in 90 steps); with the radius a
//! managed cloud settles near 3.4 points per h² (11 neighbours) and leaves the initial
//! cloud alone (docs/theory/surface-management.md).
enum class HoleSize { diameter, radius };

struct ManagementOptions {
  double r_max = 0.45;               //!< no hole of size r_max h (§2, §3.4; see HoleSize)
  double r_min = 0.2;                //!< no two points closer than r_min h (§2, §3.5)
  bool curvature_correction = true;  //!< move new points along n_approx (eqs 6–9)
  //! With curvature_correction. Midway by default: the paper's rule, as its eqs 8–9 read,
  //! leaves the new points as far off the surface as no correction does (measured on
  //! spheres and tori: 0.97 of the uncorrected error, order 2; midway: 1e-3 of it, order 4).
  CurvatureRule curvature_rule = CurvatureRule::midway;
  //! The one-rings triangulate the points within one_ring_radius h. A hole is seen only
  //! from points that see across it: with 1 (the paper's neighbourhood) a cloud whose h is
  //! halved has gaps wider than h that stay unfilled; 2 reaches across them.
  double one_ring_radius = 2.0;
  int max_fill_passes = 8;  //!< the filling is repeated for the new points (§3.4)
  HoleSize hole_size = HoleSize::radius;
  //! The circumradius above which a triangle is a hole (half a gap along curves), at
  //! smoothing length h.
  double largest_hole_radius(double h) const {
    return (hole_size == HoleSize::diameter ? 0.5 : 1.0) * r_max * h;
  }
  int max_merge_rounds = 8;  //!< merging is repeated while merged points are too close
};

struct ManagementReport {
  long added = 0;    //!< points created in holes (appended after the other points)
  long merged = 0;   //!< pairs merged into one point
  long removed = 0;  //!< interior points dropped next to boundary points
  //! Interior points on a boundary gap made the gap's boundary point (hole_filling.cpp).
  long promoted = 0;
  int fill_passes = 0;    //!< passes of the hole filling that added points
  bool filled = true;     //!< false when max_fill_passes ended the filling with holes left
  long widened_fits = 0;  //!< new or merged points whose fit needed more than h (MlsFit)
  bool changed() const { return added + merged + removed + promoted > 0; }
};

//! Merge close points, then fill holes (the filling never puts points closer than r_min h,
//! so both criteria hold afterwards). `cloud.frame` must hold consistently oriented frames of
//! the current positions, and boundary points their ν (normals for eqs 6–9, the tangent
//! planes of the one-rings and the fits). New and merged points get their position,
//! smoothing length, frame (the n_approx of their rule, on the side of the points it comes
//! from), velocity, previous velocity and every field; new points are appended, so the last
//! `added` points are the new ones. The Gaussian weight of the fits is that of the frames
//! (`frames.weight_exponent`). Afterwards the caller rebuilds neighbours, frames and
//! stencils if the report says the cloud changed. Throws std::invalid_argument unless
//! 0 < r_min < r_max, and NumericalError when a place to fill has no point within 2 h.
template <int D>
ManagementReport manage_points(PointCloud<D>& cloud, NeighbourSearch<D>& search,
                               const ManagementOptions& options, const FrameOptions& frames);

}  // namespace pellicle
