//! The frame-estimator registry: one line per estimator.
#include "pellicle/normals/colour_function.hpp"
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
      {"isosurface-offset", "the hybrid rule with extra points offset to one side",
       &make_isosurface_offset<D>},
      {"isosurface-chi2", "the hybrid rule with a second extra point, χ = 2, across (§8)",
       &make_isosurface_chi_two<D>},
      {"isosurface-guarded", "the hybrid rule; principal directions where χ has no slope",
       &make_isosurface_guarded<D>},
      {"mass-matrix", "linear isosurface through the normal equations (thesis §7.4)",
       &make_mass_matrix<D>},
      {"colour-simple", "gradient of the points' colour, linear (thesis §7.1)",
       &make_colour_simple<D>},
      {"colour-quadratic", "colour on cell centres, quadratic (thesis §7.2)",
       &make_colour_quadratic<D>},
      {"colour-cubic", "colour on nodes, cubic B-splines (thesis §7.3)", &make_colour_cubic<D>},
      {"pca", "principal components of the neighbours within three point spacings", &make_pca<D>},
  };
  return list;
}

template const std::vector<FrameEstimatorChoice<2>>& frame_estimators<2>();
template const std::vector<FrameEstimatorChoice<3>>& frame_estimators<3>();

}  // namespace pellicle
