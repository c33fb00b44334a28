#pragma once
//! The grid velocity fields the points move in. Standard MPM has one, the centre-of-mass
//! field (IJNME eqs 7–11). A contact model gives each body its own field on its own copy of
//! the grid (IJNME eqs 23–25, thesis eqs 9.4–9.6) and keeps the centre-of-mass field as
//! their sum (eqs 20–22 / 9.1–9.3). The single field is the one-field case of the same code:
//! its only field is the centre-of-mass grid, covering every point.

#include <vector>

#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/transfer.hpp"

namespace pellicle {

template <int D>
class GridFields {
 public:
  explicit GridFields(Grid<D> grid) : centre_of_mass_(std::move(grid)) {}

  //! One field per body, over the bodies' point ranges.
  void use_body_fields(const std::vector<PointRange>& bodies) {
    body_grids_.assign(bodies.size(), centre_of_mass_);
    body_points_ = bodies;
  }
  //! Every field on `grid` instead (a distributed run's window), each body's on a copy.
  void replace_grid(Grid<D> grid) {
    for (auto& g : body_grids_) g = grid;
    centre_of_mass_ = std::move(grid);
  }
  //! New point ranges of the bodies' fields (points moved between ranks).
  void set_body_ranges(const std::vector<PointRange>& bodies) {
    if (per_body()) body_points_ = bodies;
  }
  bool per_body() const { return !body_grids_.empty(); }
  //! Number of fields the points are split into (1, or one per body).
  int count() const { return per_body() ? static_cast<int>(body_grids_.size()) : 1; }
  Grid<D>& field(int k) { return per_body() ? body_grids_[k] : centre_of_mass_; }
  const Grid<D>& field(int k) const { return per_body() ? body_grids_[k] : centre_of_mass_; }
  //! The points that move in field k.
  PointRange points(int k) const { return per_body() ? body_points_[k] : PointRange{}; }
  //! The bodies' point ranges, one per field; empty with one field for all points.
  const std::vector<PointRange>& body_ranges() const { return body_points_; }
  Grid<D>& centre_of_mass() { return centre_of_mass_; }
  const Grid<D>& centre_of_mass() const { return centre_of_mass_; }

  //! Every grid once: the centre-of-mass grid, then the bodies' own.
  template <class F>
  void for_each_grid(F&& f) {
    f(centre_of_mass_);
    for (auto& g : body_grids_) f(g);
  }

  //! Per-body fields: the centre-of-mass field's mass, momentum and (when `forces`) force
  //! as the sums of the bodies' (eqs 20–21 / 9.1–9.2). Nothing to do for a single field.
  void sum_to_centre_of_mass(bool mass, bool forces);
  //! Bytes of the grid fields (one grid, or one per body plus their sum).
  std::size_t bytes_per_node() const;

 private:
  Grid<D> centre_of_mass_;
  std::vector<Grid<D>> body_grids_;
  std::vector<PointRange> body_points_;
  std::vector<NodeSpan> live_sum_;  //!< the bodies' live nodes together
};

extern template class GridFields<2>;
extern template class GridFields<3>;

}  // namespace pellicle
