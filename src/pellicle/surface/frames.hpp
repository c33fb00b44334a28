#pragma once
//! Normals and tangents of a point cloud (Suchde & Kuhnert §3.2): the normal n_i minimises
//! the weighted sum of cos² of the angles between n_i and the directions to the neighbours
//! (eq 4), the tangents complete an orthonormal frame; boundary points also get the boundary
//! normal ν. The frames are pointcloud/local_frame.hpp's (set_normal, flip_normal there).
//! The orientation is made consistent once by a sweep through the cloud and kept afterwards
//! by n_new · n_old > 0 (eq 5).

#include <vector>

#include "pellicle/pointcloud/local_frame.hpp"
#include "pellicle/pointcloud/neighbour_search.hpp"
#include "pellicle/pointcloud/weights.hpp"
#include "pellicle/surface/point_cloud.hpp"

namespace pellicle {

struct FrameOptions {
  double weight_exponent = 2.0;  //!< c of the Gaussian weight
};

//! Frames of every point from its neighbours. With `keep_side` the new normal takes the side
//! of the point's current one (eq 5) and 3D tangents are continued from the current ones;
//! without it the signs are arbitrary until `orient_consistently`. Throws NumericalError
//! when a point has too few neighbours to define a normal.
template <int D>
void estimate_frames(PointCloud<D>& cloud, const NeighbourLists& neighbours,
                     const FrameOptions& options, bool keep_side);

//! The sweep of §3.2: from a seed point through the neighbourhoods, each normal takes the
//! side of the neighbour it is reached from. Each connected piece then faces along
//! `reference` normals where given (the exact normals of a generated cloud), else outward
//! from its centroid.
template <int D>
void orient_consistently(PointCloud<D>& cloud, const NeighbourLists& neighbours,
                         const std::vector<Vec<D>>* reference = nullptr);

}  // namespace pellicle
