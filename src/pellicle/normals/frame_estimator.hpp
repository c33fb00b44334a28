#pragma once
//! Local frames of membrane points: in 2D the unit tangent t and normal n of the curve (n is t
//! turned +90°); in 3D the unit normal n and an in-plane tangent t1 (t2 = n × t1). The
//! membrane law works in these frames (thesis §5.3 step 7). Estimators are chosen by name per
//! membrane body; they work on a body's points in one call.

#include <memory>
#include <string>
#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/geometry/membrane_geometry.hpp"

namespace pellicle {

template <int D>
class FrameEstimator {
 public:
  virtual ~FrameEstimator() = default;
  //! Frames of points [begin, end) of `position` from their current places. `tangent`
  //! holds the previous tangents on entry (3D: kept continuous in time) and the new ones on
  //! return.
  virtual void estimate(const std::vector<Vec<D>>& position, long begin, long end,
                        std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) = 0;
};

template <int D>
struct FrameEstimatorChoice {
  std::string name;
  std::string summary;
  std::unique_ptr<FrameEstimator<D>> (*make)(const MembraneConnectivity& connectivity);
};

//! Registered estimators (registry.cpp).
template <int D>
const std::vector<FrameEstimatorChoice<D>>& frame_estimators();

//! t1 continued from the previous tangent, projected into the plane normal to n; a fixed
//! axis when there is none yet. Keeps in-plane directions from jumping between steps.
Vec3 continue_tangent(const Vec3& previous, const Vec3& normal);

}  // namespace pellicle
