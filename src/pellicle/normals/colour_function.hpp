#pragma once
//! The colour-function rivals of thesis chapter 7, for comparison with the isosurface method.
//! Every membrane point carries colour 1; the normal is the gradient of a grid colour field:
//!   simple    (eqs 7.2–7.3): node normals n_i = Σ_p ∇N_i(x_p) with the linear tent, then
//!             n_p = Σ_i N_i(x_p) n_i;
//!   quadratic (eqs 7.4–7.5): cell colours c_c = Σ_p S2(x_p − x_c) with quadratic B-splines on
//!             cell centres, node normals n_i = Σ_c c_c ∇N_i(x_c), then interpolated as above;
//!   cubic     (eqs 7.6–7.7): node colours c_i = Σ_p S3(x_p − x_i) with cubic B-splines, and
//!             n_p = Σ_i c_i ∇S3(x_p − x_i).
//! The colour of a lone membrane peaks on it, so its gradient there is weak and noisy (the
//! thesis found them the least effective); the signs are settled by complete_frames.
//! Also the principal-component estimator of point-cloud processing:
//!   pca:      the direction of least spread of the neighbours within three point spacings,
//!             weighted by (1 − (d/r)²)², about their weighted mean (principal_directions.hpp).

#include <memory>

#include "pellicle/normals/frame_estimator.hpp"

namespace pellicle {

template <int D>
std::unique_ptr<FrameEstimator<D>> make_colour_simple(const FrameSetup<D>& setup);
template <int D>
std::unique_ptr<FrameEstimator<D>> make_colour_quadratic(const FrameSetup<D>& setup);
template <int D>
std::unique_ptr<FrameEstimator<D>> make_colour_cubic(const FrameSetup<D>& setup);
template <int D>
std::unique_ptr<FrameEstimator<D>> make_pca(const FrameSetup<D>& setup);

}  // namespace pellicle
