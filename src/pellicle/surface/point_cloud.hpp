#pragma once
//! The Lagrangian point cloud of a moving curve (D = 2) or surface (D = 3) (Suchde & Kuhnert
//! §2–3): points without connectivity, each with its smoothing length h, its local frame,
//! its velocity history for the second-order movement (eq 3) and the fields a PDE carries.
//! Points are added and removed by point management; every per-point array follows.

#include <cstdint>
#include <string>
#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/pointcloud/point_set.hpp"

namespace pellicle {

template <int D>
class PointCloud {
 public:
  //! Positions x_i.
  std::vector<Vec<D>> position;
  //! Smoothing length h_i: the neighbourhood radius and the spacing scale (§2).
  std::vector<double> smoothing_length;
  //! Orthonormal right-handed frame per point, columns (t_1, t_2, n) in 3D and (t, n) in 2D:
  //! R^T of eq 22.
  std::vector<Mat<D>> frame;
  std::vector<std::uint8_t> boundary;  //!< 1 on the manifold's boundary
  //! ν at boundary points: normal to the boundary, in the manifold's tangent space, pointing
  //! out of the manifold (§3.2); zero elsewhere.
  std::vector<Vec<D>> boundary_normal;
  //! 1 at boundary points where the boundary turns (its boundary neighbours spread in two
  //! directions); set with the frames (frames.hpp).
  std::vector<std::uint8_t> corner;
  std::vector<Vec<D>> velocity;  //!< v^(n)
  //! v^(n−1), for the second-order movement (eq 3); valid where has_previous_velocity.
  std::vector<Vec<D>> previous_velocity;
  std::vector<std::uint8_t> has_previous_velocity;
  //! The chamber of §3.6: which connected manifold the point belongs to. Contact is detected
  //! between chambers (and between facing parts of one chamber); chambers are joined by
  //! delete and merge contact and split when a surface comes apart (surface/chambers.hpp).
  std::vector<int> chamber;
  //! Which of the case's surfaces the point comes from (0, 1, …): the contact rules are
  //! chosen by it, whatever the chambers have become since.
  std::vector<int> surface;
  //! The sign of the signed distance DC_i to the nearest other part at the last step it had
  //! one within h (§3.6), 0 when it had none: a change of sign is a penetration.
  std::vector<std::int8_t> contact_side;

  std::size_t size() const { return position.size(); }
  Vec<D> normal(std::size_t i) const { return frame[i].col(D - 1); }

  //! Add a point with an identity frame, zero velocity and zero fields, in chamber 0 of
  //! surface 0; returns its index.
  std::size_t add_point(const Vec<D>& x, double h, bool on_boundary);
  //! Give point `to` the chamber, surface and contact side of point `from` (a point made
  //! from others by point management belongs where they do).
  void inherit_identity(std::size_t to, std::size_t from) {
    chamber[to] = chamber[from];
    surface[to] = surface[from];
    contact_side[to] = contact_side[from];
  }
  //! Number of distinct chambers (0 for an empty cloud).
  int chamber_count() const;

  //! Self-contact (§3.6): two points of one chamber whose normals are closer to opposite
  //! than this (n_i·n_j below it) lie on different parts of it, e.g. the two sides of a
  //! pinching neck. −2 (below any n_i·n_j): a chamber is one part.
  double facing_limit = -2.0;
  //! Keep the points of surfaces s and t on different parts even once they share a chamber:
  //! delete contact joins two chambers into one and goes on between them.
  void keep_apart(int s, int t);
  bool kept_apart(int s, int t) const {
    return s != t && s < apart_size_ && t < apart_size_ && apart_[s * apart_size_ + t];
  }
  //! Whether point j lies on the part of point i, were i's normal n: the points S_i may hold
  //! (§3.6), the others being S_i^ext. Same chamber, surfaces not kept apart, normals not
  //! facing.
  bool on_part(std::size_t j, std::size_t i, const Vec<D>& n) const {
    return chamber[j] == chamber[i] && !kept_apart(surface[i], surface[j]) &&
           normal(j).dot(n) >= facing_limit;
  }
  bool same_part(std::size_t i, std::size_t j) const { return on_part(j, i, normal(i)); }
  //! Whether some pair of points may lie on different parts (several chambers, surfaces kept
  //! apart, or self-contact on): neighbourhoods must then be split (surface/chambers.hpp).
  bool has_parts() const;
  //! Remove the points whose flag is set, keeping the order of the others.
  void remove_points(const std::vector<std::uint8_t>& remove);

  //! Scalar fields carried by the points (φ, φ of the previous step, …), by name.
  int add_field(const std::string& name, double initial = 0.0);
  int field_index(const std::string& name) const;  //!< −1 when absent
  std::vector<double>& field(int index) { return field_values_[index]; }
  const std::vector<double>& field(int index) const { return field_values_[index]; }
  const std::vector<std::string>& field_names() const { return field_names_; }

  //! Increases whenever points are added or removed: neighbour searches and stencils built
  //! for another generation are stale.
  long generation() const { return generation_; }
  //! The view the point-cloud algorithms read (neighbour search).
  operator PointSet<D>() const { return {position, smoothing_length, generation_}; }

 private:
  std::vector<std::uint8_t> apart_;  //!< apart_size_² flags of keep_apart
  int apart_size_ = 0;
  std::vector<std::string> field_names_;
  std::vector<std::vector<double>> field_values_;
  long generation_ = 0;
};

}  // namespace pellicle
