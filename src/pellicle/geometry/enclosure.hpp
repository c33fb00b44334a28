#pragma once
//! The inside of a membrane: the region a closed curve (2D) or surface (3D) encloses, or one
//! that is closed by the planes its open ends lie on (the symmetry planes of a quarter or half
//! model, a wall it is sealed against). Used to fill a membrane with gas (thesis §6.2: the gas
//! points fill the bag) and to count gas points that have left it.
//!
//! The membrane is taken as segments between consecutive points (2D) or the triangles it was
//! generated with (3D). An open membrane is closed by mirroring: each open end (2D) or
//! boundary edge (3D) is joined to its mirror image in the plane it lies on, and the whole
//! set is mirrored in every such plane, so a quarter circle becomes the full circle. Inside
//! is decided by the parity of crossings of a ray in +x.

#include <array>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/geometry/membrane_geometry.hpp"
#include "pellicle/geometry/region.hpp"

namespace pellicle {

//! The plane x[axis] = position (a grid face).
struct MirrorPlane {
  int axis = 0;
  double position = 0.0;
};

template <int D>
class Enclosure {
 public:
  //! The membrane points [begin, end) of `x` connected as `connectivity` says (2D: in order,
  //! closed or open; 3D: its triangles, indices relative to begin). Open ends must lie within
  //! `tolerance` of one of `planes`; otherwise problem() says which end does not.
  Enclosure(const std::vector<Vec<D>>& x, long begin, long end,
            const MembraneConnectivity& connectivity, const std::vector<MirrorPlane>& planes,
            double tolerance);

  //! Empty when the membrane encloses a region; else what keeps it open.
  const std::string& problem() const { return problem_; }
  //! x lies inside the closed membrane (or its mirror images).
  bool inside(const Vec<D>& x) const;
  //! Distance from x to the membrane or its mirror images (not to the mirror planes); when it
  //! is at least `limit`, some value not below `limit` (the search stops there).
  double distance(const Vec<D>& x, double limit = std::numeric_limits<double>::infinity()) const;
  //! Box around the membrane and its mirror images.
  Box<D> bounds() const { return bounds_; }
  //! The planes the membrane's open ends lie on (those that close it).
  const std::vector<MirrorPlane>& closing_planes() const { return used_; }

 private:
  struct Piece {
    std::array<Vec<D>, D> corner;  //!< segment ends (2D) or triangle corners (3D)
    bool membrane;                 //!< false: a join to a mirror image, on a plane
    int plane;                     //!< the plane a join lies on (−1 for membrane pieces)
  };
  void mirror(const MirrorPlane& plane, int index);
  void index_pieces();
  long bucket(const Vec<D>& x) const;

  std::vector<Piece> pieces_;
  std::vector<MirrorPlane> used_;
  Box<D> bounds_{};
  std::string problem_;
  // Buckets of a uniform grid over the pieces: for the ray (by the cross-section y or (y, z))
  // and for distances (by cell).
  double bucket_size_ = 1.0;
  Vec<D> origin_ = Vec<D>::Zero();
  IVec<D> buckets_ = IVec<D>::Ones();
  std::vector<std::vector<int>> cell_pieces_, row_pieces_;
};

//! Region of the points inside the membrane and at least `gap` from it.
template <int D>
RegionPtr<D> make_enclosed_region(std::shared_ptr<const Enclosure<D>> enclosure, double gap);

extern template class Enclosure<2>;
extern template class Enclosure<3>;

}  // namespace pellicle
