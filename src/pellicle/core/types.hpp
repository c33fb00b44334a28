#pragma once
//! Small fixed-size algebra types shared by every module, and the symmetric-tensor storage
//! used for point stresses and strains.

#include <Eigen/Core>

#include <array>
#include <cstdint>

namespace pellicle {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;
template <int D>
using Mat = Eigen::Matrix<double, D, D>;
template <int D>
using IVec = Eigen::Matrix<int, D, 1>;
using Vec2 = Vec<2>;
using Vec3 = Vec<3>;
using Mat3 = Mat<3>;

//! Number of stored components of a symmetric tensor in D dimensions. 2D keeps the
//! out-of-plane normal component (plane strain stress, plane stress strain, axisymmetric hoop).
template <int D>
constexpr int kSymComponents = D == 2 ? 4 : 6;

//! Symmetric tensor in Voigt-like order.
//! 2D: (xx, yy, zz, xy)  — zz is the out-of-plane (or hoop, in axisymmetry) component.
//! 3D: (xx, yy, zz, yz, xz, xy).
template <int D>
using Sym = Eigen::Matrix<double, kSymComponents<D>, 1>;

//! Expand stored symmetric components into a full 3x3 tensor (2D: no xz, yz coupling).
template <int D>
inline Mat3 to_mat3(const Sym<D>& s) {
  Mat3 m;
  if constexpr (D == 2) {
    m << s[0], s[3], 0.0, s[3], s[1], 0.0, 0.0, 0.0, s[2];
  } else {
    m << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
  }
  return m;
}

//! Collect the stored components of the symmetric part of a 3x3 tensor.
template <int D>
inline Sym<D> from_mat3(const Mat3& m) {
  Sym<D> s;
  if constexpr (D == 2) {
    s << m(0, 0), m(1, 1), m(2, 2), 0.5 * (m(0, 1) + m(1, 0));
  } else {
    s << m(0, 0), m(1, 1), m(2, 2), 0.5 * (m(1, 2) + m(2, 1)), 0.5 * (m(0, 2) + m(2, 0)),
        0.5 * (m(0, 1) + m(1, 0));
  }
  return s;
}

//! Double contraction a : b of two symmetric tensors given in stored form.
template <int D>
inline double contract(const Sym<D>& a, const Sym<D>& b) {
  double r = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  for (int k = 3; k < kSymComponents<D>; ++k) r += 2.0 * a[k] * b[k];
  return r;
}

//! Trace of a symmetric tensor in stored form.
template <int D>
inline double trace(const Sym<D>& s) {
  return s[0] + s[1] + s[2];
}

//! s + value·I: `value` added to the three normal components. Built from the components, not
//! by updating `head<3>()` in place: a tensor written in pieces and then read as one vector
//! stalls store forwarding (docs/theory/performance.md, "Store forwarding").
template <int D>
inline Sym<D> add_to_normal(const Sym<D>& s, double value) {
  if constexpr (D == 2) {
    return Sym<2>(s[0] + value, s[1] + value, s[2] + value, s[3]);
  } else {
    Sym<D> r;
    for (int i = 0; i < 3; ++i) r[i] = s[i] + value;
    for (int i = 3; i < 6; ++i) r[i] = s[i];
    return r;
  }
}

}  // namespace pellicle
