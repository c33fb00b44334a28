#pragma once
//! Point management of a moving cloud (Suchde & Kuhnert §3.4–3.5): holes are filled at the
//! circumcentres of large triangles of each point's local one-ring triangulation (with the
//! curvature correction of eqs 6–9), points closer than r_min h are merged (boundary points
//! kept in place), and every quantity a point carries is interpolated to new and merged
//! points by a second-order moving least-squares fit. Every choice the paper leaves open is
//! written down in docs/theory/surface-management.md.

#include "pellicle/surface/frames.hpp"
#include "pellicle/surface/neighbours.hpp"

namespace pellicle {

struct ManagementOptions {
  double r_max = 0.45;               //!< no hole of circumradius r_max h (§2, §3.4)
  double r_min = 0.2;                //!< no two points closer than r_min h (§2, §3.5)
  bool curvature_correction = true;  //!< move new points along n_approx (eqs 6–9)
  int max_fill_passes = 8;           //!< the filling is repeated for the new points (§3.4)
};

struct ManagementReport {
  long added = 0;    //!< points created in holes
  long merged = 0;   //!< pairs merged into one point
  long removed = 0;  //!< interior points dropped next to boundary points
  bool changed() const { return added + merged + removed > 0; }
};

//! Fill holes, then merge close points. `cloud.frame` must hold the frames of the current
//! positions (normals for eqs 6–9 and the tangent planes of the fits). New and merged points
//! get their position, smoothing length, frame (normal from eq 6, sides kept), velocity,
//! previous velocity and every field. Afterwards the caller rebuilds neighbours, frames and
//! stencils if the report says the cloud changed.
template <int D>
ManagementReport manage_points(PointCloud<D>& cloud, NeighbourSearch<D>& search,
                               const ManagementOptions& options, const FrameOptions& frames);

}  // namespace pellicle
