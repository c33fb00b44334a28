#pragma once
//! A surface's frames from a membrane frame estimator (normals/): the two store the same frame
//! (pointcloud/local_frame.hpp), the surfaces as one matrix per point, the membranes as its
//! normal and first tangent, so any registered estimator (isosurface, colour function, PCA …)
//! can stand in for the surfaces' eq 4 normals (Suchde & Kuhnert §3.2). Boundary normals ν
//! and corner flags are not touched: only the §3.2 construction (frames.hpp) sets them.

#include "pellicle/normals/frame_estimator.hpp"
#include "pellicle/surface/point_cloud.hpp"

namespace pellicle {

//! Frames of every point of `cloud` by `estimator`, the cloud taken as one body. With
//! `keep_side` the cloud's current frames are the estimator's previous ones (normals keep
//! their side, eq 5, and 3D tangents are continued); without it the estimator orients the
//! normals by its own rule (FrameSetup::orientation).
template <int D>
void estimate_frames(FrameEstimator<D>& estimator, PointCloud<D>& cloud, bool keep_side);

}  // namespace pellicle
