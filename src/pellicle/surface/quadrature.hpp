#pragma once
//! Integrals over a point cloud: each point stands for a third of the area of its one-ring
//! triangles (one_ring.hpp; half the length of its two segments on a curve). Where the
//! one-rings of neighbouring points agree (a Delaunay cloud) every triangle is counted once
//! in all, so Σ_i A_i is the area of the triangulated surface, second-order accurate; it is
//! what history.csv's `area` and `total_phi` = Σ_i A_i φ_i use (the half pipe's
//! conservation check, Suchde & Kuhnert §4.2.2).

#include <vector>

#include "pellicle/pointcloud/neighbour_search.hpp"
#include "pellicle/surface/point_cloud.hpp"

namespace pellicle {

//! A_i for every point, from neighbour lists within h (frames must be current).
template <int D>
void point_areas(const PointCloud<D>& cloud, const NeighbourLists& neighbours,
                 std::vector<double>& area);

struct SurfaceIntegrals {
  double area = 0.0;      //!< Σ_i A_i
  double integral = 0.0;  //!< Σ_i A_i u_i (0 without u)
  //! The volume (2D: area) a closed surface encloses, by the divergence theorem
  //! V = (1/D) ∮ x · n dA ≈ (1/D) Σ_i A_i x_i · n_i (outward normals; meaningless when open).
  double enclosed = 0.0;
};

//! The area, the enclosed volume and, with `u`, ∫ u dA (`areas` is scratch for the A_i).
template <int D>
SurfaceIntegrals integrate(const PointCloud<D>& cloud, const NeighbourLists& neighbours,
                           const std::vector<double>* u, std::vector<double>& areas);

}  // namespace pellicle
