#pragma once
//! Local frames of membrane points: in 2D the unit tangent t and normal n of the curve (n is t
//! turned +90°); in 3D the unit normal n and an in-plane tangent t1 (t2 = n × t1): the
//! columns of pointcloud/local_frame.hpp's frame, kept as two arrays (frame_of assembles the
//! frame; 3D tangents are continued by its continue_tangent). The membrane law works in these
//! frames (thesis §5.3 step 7). Estimators are chosen by name per membrane body; they work on
//! a body's points in one call.

#include <memory>
#include <string>
#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/geometry/enclosure.hpp"
#include "pellicle/geometry/membrane_geometry.hpp"
#include "pellicle/pointcloud/cell_groups.hpp"

namespace pellicle {

//! How estimators that cannot tell inside from outside (the isosurface and colour-function
//! methods, PCA) choose the sign of the normal the first time. Afterwards every normal keeps
//! the side of its previous value (n · n_previous > 0).
enum class NormalOrientation {
  propagate,  //!< from the body's first point through neighbours, so neighbours agree
  outward,    //!< away from the centroid of the body's points (closed curves and surfaces)
  //! away from the points of the body the membrane encloses (its gas): each normal faces
  //! away from the mean of the enclosed points within a cell of it, so pressure pushes along
  //! +n whatever the membrane's shape (points with none near follow their neighbours)
  away_from_inside,
};

//! The rule for first signs, and for away_from_inside the enclosed body's points (those
//! within a cell of the membrane suffice: WithinACell).
template <int D>
struct FrameOrientation {
  FrameOrientation(NormalOrientation rule = NormalOrientation::propagate,
                   std::vector<Vec<D>> inside = {})
      : rule(rule), inside(std::move(inside)) {}
  NormalOrientation rule;
  std::vector<Vec<D>> inside;
};

//! What an estimator may need to know: the generated connectivity (only `connectivity`
//! uses it) and the background grid the local constructions live on.
template <int D>
struct FrameSetup {
  MembraneConnectivity connectivity;
  Vec<D> grid_origin = Vec<D>::Zero();  //!< position of a grid node
  double cell = 1.0;
  FrameOrientation<D> orientation;
  //! Wall and symmetry faces of the grid: an open end on one continues into its mirror image.
  std::vector<MirrorPlane> mirrors;
  unsigned seed = 20000;  //!< seeds the isosurface method's extra points (reproducible)
};

//! Part of a membrane body, for a distributed run whose ranks each hold some of its points
//! (dist/halo_frames.hpp): the points whose frames are wanted and the body's points around
//! them, in the body's generation order.
struct BodyPart {
  std::vector<long> index;   //!< each point's index in the body as built, ascending
  std::vector<char> wanted;  //!< 1 where the point's frame is wanted
  long count = 0;            //!< points of the whole body
  //! The FrameSetup::mirrors the whole body touches (FrameEstimator::planes_touched, ORed
  //! over the parts).
  unsigned planes = 0;
};

template <int D>
class FrameEstimator {
 public:
  virtual ~FrameEstimator() = default;
  //! Frames of points [begin, end) of `position` from their current places. `normal` and
  //! `tangent` hold the previous frames on entry (zero the first time): normals keep their
  //! side, 3D tangents are continued, so the membrane strain never sees a frame jump.
  virtual void estimate(const std::vector<Vec<D>>& position, long begin, long end,
                        std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) = 0;

  //! Frames from parts of the body. Once every point of the body has a frame and estimate
  //! has run once on the whole body (which settles first signs), a point's frame depends
  //! only on the body's points in the grid cells within reach() cells of its own (the
  //! (2 reach + 1)^D cells around it), or, for connectivity frames, on its neighbours in the
  //! mesh, which lie that near unless the membrane is torn apart. −1 (the default): a frame
  //! depends on the whole body, as for a scale taken over all its points.
  virtual int reach() const { return -1; }
  //! The mirror planes (bit k: FrameSetup::mirrors[k]) one of points [begin, end) lies on.
  virtual unsigned planes_touched(const std::vector<Vec<D>>& /*position*/, long /*begin*/,
                                  long /*end*/) const {
    return 0;
  }
  //! Frames of `part`'s wanted points: `position`, `normal` and `tangent` hold all of its
  //! points, with their previous frames on entry, every normal set. The wanted frames come
  //! out bitwise as estimate on the whole body gives them. False, with nothing promised,
  //! when the part lacks a point a wanted frame needs or the estimator has no part of it.
  virtual bool estimate_part(const BodyPart& /*part*/, const std::vector<Vec<D>>& /*position*/,
                             std::vector<Vec<D>>& /*normal*/, std::vector<Vec<D>>& /*tangent*/) {
    return false;
  }
};

template <int D>
struct FrameEstimatorChoice {
  std::string name;
  std::string summary;
  std::unique_ptr<FrameEstimator<D>> (*make)(const FrameSetup<D>& setup);
};

//! Registered estimators (registry.cpp).
template <int D>
const std::vector<FrameEstimatorChoice<D>>& frame_estimators();

//! Complete unit normals of points [begin, end) to frames, with signs settled: a normal
//! keeps the side of the previous one (given on entry in `previous`, zero if none); points
//! without a previous normal are oriented by `orientation`. 2D tangents are n turned −90°
//! (so n is t turned +90°); 3D tangents are continued from the previous ones.
template <int D>
void complete_frames(const std::vector<Vec<D>>& position, long begin, long end,
                     const FrameOrientation<D>& orientation, const std::vector<Vec<D>>& previous,
                     std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent, double cell);

//! The side each normal of points [begin, end) faces relative to the enclosed points: +1 away
//! from the mean of those within a cell, −1 towards it, 0 when none is that near.
template <int D>
std::vector<int> sides_from_inside(const std::vector<Vec<D>>& position, long begin, long end,
                                   const std::vector<Vec<D>>& normal,
                                   const std::vector<Vec<D>>& inside, double cell);

//! Whether a place lies within a cell of one of the points [begin, end) of `position` (a
//! membrane): the enclosed points for which this holds are all that sides_from_inside looks
//! at, so a membrane's FrameOrientation::inside need keep only those, in their order.
template <int D>
class WithinACell {
 public:
  WithinACell(const std::vector<Vec<D>>& position, long begin, long end, double cell);
  bool operator()(const Vec<D>& y) const;

 private:
  std::vector<Vec<D>> points_;
  double cell_;
  CellGroups<D> groups_;  //!< of points_
};

}  // namespace pellicle
