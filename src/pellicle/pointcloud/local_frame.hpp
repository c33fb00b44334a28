#pragma once
//! The local frame of a point of a curve (D = 2) or surface (D = 3), one type for every
//! unconnected-point algorithm: a Mat<D> whose columns are (t, n) in 2D and (t_1, t_2, n) in
//! 3D, orthonormal and right-handed, so n is t turned +90° in 2D and t_2 = n × t_1 in 3D. It
//! is R^T of Suchde & Kuhnert eq 22. The meshfree surfaces store one per point
//! (surface/point_cloud.hpp); the membrane estimators (normals/frame_estimator.hpp) store the
//! same frame as its two columns n and t_1 in two arrays, what the membrane law reads (thesis
//! §5.3 step 7). `frame_of`, `normal_of` and `tangent_of` convert between the two, so a
//! surface's frames can come from a membrane estimator and a membrane's from the surfaces' §3.2
//! construction. Header-only: the frame loops inline these.

#include <Eigen/Geometry>

#include <cmath>

#include "pellicle/core/types.hpp"

namespace pellicle {

template <int D>
Vec<D> normal_of(const Mat<D>& frame) {
  return frame.col(D - 1);
}

//! t in 2D, t_1 in 3D.
template <int D>
Vec<D> tangent_of(const Mat<D>& frame) {
  return frame.col(0);
}

//! The surfaces' rule for t_1 (frames.hpp): `previous` projected into the plane normal to the
//! unit n when it lies off the normal (|projection|² > 10⁻⁶), else the coordinate axis least
//! aligned with n, projected.
inline Vec3 tangent_in_plane(const Vec3& n, const Vec3& previous) {
  Vec3 t = previous - previous.dot(n) * n;
  if (t.squaredNorm() > 1e-6) return t.normalized();
  int axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  t = Vec3::Unit(axis) - n[axis] * n;
  return t.normalized();
}

//! The membrane estimators' rule for t_1 (frame_estimator.hpp): the previous tangent projected
//! into the plane normal to n, unless it (nearly) vanishes there (|projection|² < 10⁻¹²): then
//! the x axis, or the y axis when n is within about 26° of x, projected. It differs from
//! tangent_in_plane only where the previous tangent is (close to) along n.
inline Vec3 continue_tangent(const Vec3& previous, const Vec3& n) {
  Vec3 t = previous - previous.dot(n) * n;
  if (t.squaredNorm() < 1e-12) {
    const Vec3 axis = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    t = axis - axis.dot(n) * n;
  }
  return t.normalized();
}

//! The frame with unit normal n and first tangent t_1 (3D; t_1 unit and normal to n). In 2D
//! the tangent is n turned −90° and `tangent` is not read: a membrane's 2D (t, n) pair always
//! has t = n turned −90°.
template <int D>
Mat<D> frame_of(const Vec<D>& n, const Vec<D>& tangent) {
  Mat<D> f;
  if constexpr (D == 2) {
    (void)tangent;
    f.col(0) = Vec2(n.y(), -n.x());  // (t, n) right-handed
    f.col(1) = n;
  } else {
    f.col(0) = tangent;
    f.col(1) = n.cross(tangent);
    f.col(2) = n;
  }
  return f;
}

//! The frame with unit normal n, its first tangent from `hint` by the surfaces' rule
//! (tangent_in_plane; 3D only).
template <int D>
Mat<D> frame_from(const Vec<D>& n, const Vec<D>& hint) {
  if constexpr (D == 2)
    return frame_of<2>(n, hint);
  else
    return frame_of<3>(n, tangent_in_plane(n, hint));
}

//! Give a frame the normal n (unit), continuing its first tangent into the new tangent plane.
template <int D>
void set_normal(Mat<D>& frame, const Vec<D>& n) {
  frame = frame_from<D>(n, frame.col(0));
}

//! Reverse the normal of a frame, keeping it right-handed.
template <int D>
void flip_normal(Mat<D>& frame) {
  frame.col(D - 1) = -frame.col(D - 1);
  frame.col(D - 2) = -frame.col(D - 2);  // keeps det = +1
}

}  // namespace pellicle
