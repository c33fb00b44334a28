#pragma once
//! Mirror images of membrane points for the connectivity-free estimators. A quarter or half
//! model's membrane ends on symmetry planes (the grid's slip faces) or walls, and continues
//! beyond them as its mirror image. A local construction near such an end sees only one side
//! of it: the isosurface fit of the end cell is an extrapolation there, and PCA's or a colour
//! function's neighbourhood is cut in half, so the end normals tilt off the plane's normal
//! (Sulsky & York 2000 §8: "endpoints of a membrane segment might not have a completely
//! accurate normal"). Adding the images as extra points makes the end an interior point of
//! the local fit, as the connectivity estimator's mirrored neighbour does (thesis eq 7.1).

#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/geometry/enclosure.hpp"

namespace pellicle {

//! The planes of `mirrors` (bit k for mirrors[k]) that a point of [begin, end) lies on,
//! within a hundredth of `cell`. ORed over the parts of a body, the body's.
template <int D>
unsigned mirrors_touched(const std::vector<Vec<D>>& x, long begin, long end,
                         const std::vector<MirrorPlane>& mirrors, double cell);

//! Of the `touched` planes of `mirrors`, at most one per axis (the first): the planes the
//! membrane ends on.
std::vector<MirrorPlane> planes_ended_on(unsigned touched, const std::vector<MirrorPlane>& mirrors);

//! The planes the points [begin, end) of `x` end on: the two above together.
template <int D>
std::vector<MirrorPlane> planes_ended_on(const std::vector<Vec<D>>& x, long begin, long end,
                                         const std::vector<MirrorPlane>& mirrors, double cell) {
  return planes_ended_on(mirrors_touched<D>(x, begin, end, mirrors, cell), mirrors);
}

//! Points [begin, end) of `x` (as entries 0 … end − begin − 1) followed by their mirror
//! images in each plane of `mirrors` that one of them lies on (within a hundredth of `cell`):
//! the images of the points within `band` of that plane. Points within `band` of two or three
//! such planes on different axes also get their images in both or all three (the corner's).
template <int D>
std::vector<Vec<D>> with_mirror_images(const std::vector<Vec<D>>& x, long begin, long end,
                                       const std::vector<MirrorPlane>& mirrors, double cell,
                                       double band);

//! The same with the planes given (`ended_on`, as planes_ended_on finds them): for a part of
//! a body, whose own points may not reach the planes the whole body ends on.
template <int D>
std::vector<Vec<D>> with_images_in(const std::vector<Vec<D>>& x, long begin, long end,
                                   const std::vector<MirrorPlane>& ended_on, double cell,
                                   double band);

}  // namespace pellicle
