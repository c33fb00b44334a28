#pragma once
//! The connectivity estimator: frames from the order in which points were generated.
//! 2D (thesis eq 7.1): t_p ∥ x_{p+1} − x_{p−1}, one-sided at the ends of an open curve.
//! 3D: n_p ∥ Σ over the triangles at p of (x_b − x_a) × (x_c − x_a), the area-weighted
//! normal of the surface mesh the points were generated from.

#include <memory>

#include "pellicle/normals/frame_estimator.hpp"

namespace pellicle {

template <int D>
std::unique_ptr<FrameEstimator<D>> make_connectivity_estimator(const FrameSetup<D>& setup);

}  // namespace pellicle
