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

  std::size_t size() const { return position.size(); }
  Vec<D> normal(std::size_t i) const { return frame[i].col(D - 1); }

  //! Add a point with an identity frame, zero velocity and zero fields; returns its index.
  std::size_t add_point(const Vec<D>& x, double h, bool on_boundary);
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
  std::vector<std::string> field_names_;
  std::vector<std::vector<double>> field_values_;
  long generation_ = 0;
};

}  // namespace pellicle
