//! The frame-estimator registry: one line per estimator.
#include "pellicle/normals/connectivity.hpp"
#include "pellicle/normals/frame_estimator.hpp"
#include "pellicle/normals/isosurface.hpp"

namespace pellicle {

template <int D>
const std::vector<FrameEstimatorChoice<D>>& frame_estimators() {
  static const std::vector<FrameEstimatorChoice<D>> list = {
      {"connectivity", "neighbours in generation order (thesis eq 7.1); mesh normals in 3D",
       &make_connectivity_estimator<D>},
      {"isosurface-linear", "local isosurface, bi/trilinear χ per cell (Sulsky & York 2000 §3)",
       &make_isosurface_linear<D>},
      {"isosurface-quadratic", "local isosurface, quadratic B-spline χ (Sulsky & York 2000 §5)",
       &make_isosurface_quadratic<D>},
      {"isosurface-hybrid", "quadratic, linear or joined cells by point count (§8)",
       &make_isosurface_hybrid<D>},
  };
  return list;
}

template const std::vector<FrameEstimatorChoice<2>>& frame_estimators<2>();
template const std::vector<FrameEstimatorChoice<3>>& frame_estimators<3>();

}  // namespace pellicle
