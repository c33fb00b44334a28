#pragma once
//! A PDE on a moving curve or surface (Suchde & Kuhnert §3–4): the Lagrangian point cloud,
//! its geometry (neighbours, frames, GFDM stencils, curvature), its velocity field and the
//! PDE it carries. One step reads as the paper's algorithm:
//!   1. velocity  v⁽ⁿ⁾ from the case's formulas at the current points (φⁿ, n, κ)
//!   2. move      eq 3 (eq 2 at the first step)
//!   3. geometry  neighbours (split by part: S_i and S_i^ext, §3.6), frames kept on their
//!                side (eq 5), stencils (eqs 17–27)
//!   3b. contact  signed distances to other parts, penetration and near contact, the
//!                responses of §3.6 (contact.hpp); geometry again if points moved or went
//!   4. manage    fill holes, merge close points (§3.4–3.5) once points have moved a tenth
//!                of h since the last time; geometry again if the cloud changed
//!   5. pde       one implicit step on the new cloud with ∇_M · v⁽ⁿ⁺¹⁾ (eq 29, eq 45)
//!   6. observe   chambers split by connected components, output, failure checks

#include <array>
#include <memory>
#include <vector>

#include "pellicle/core/observer.hpp"
#include "pellicle/surface/contact.hpp"
#include "pellicle/surface/gfdm.hpp"
#include "pellicle/surface/management.hpp"
#include "pellicle/surface/movement.hpp"
#include "pellicle/surface/pde.hpp"
#include "pellicle/surface/sparse_system.hpp"

namespace pellicle {

struct SurfaceSettings {
  double dt = 0.0, end_time = 0.0;
  MovementOrder movement = MovementOrder::second;
  FrameOptions frames;
  GfdmOptions gfdm;
  //! Tilt the eq 4 normals by the fitted slope (gfdm.hpp, refine_normals) before the
  //! stencils are built: second-order normals and curvature.
  bool refine_normals = true;
  bool manage = true;
  ManagementOptions management;
  //! Management runs once some point has moved this × its h since management last ran
  //! (0: every step). The cloud distorts no faster than its points move, and the one-ring
  //! search of the management is the dearest stage of a step.
  double management_interval = 0.1;
  LinearSolverOptions solver;
  double rebuild_fraction = 0.25;  //!< neighbour tree kept until points move this × h
  //! Points with fewer neighbours within h take this many nearest ones (neighbours.hpp):
  //! 10 on surfaces, 5 on curves (monomials to fit: 6 and 3).
  int minimum_neighbours = 0;
  //! Smooth κ with eq 40, twice, before formulas read it (curvature flows need it).
  bool smooth_curvature = true;
  //! Contact between the surfaces of a case and within each (§3.6).
  ContactOptions contact;
};

template <int D>
class SurfaceSimulation;

//! Called after every step (output writers, progress).
template <int D>
using SurfaceObserver = RunObserver<SurfaceSimulation<D>>;

template <int D>
class SurfaceSimulation {
 public:
  //! Sets up the geometry of the initial cloud (normals oriented along `reference` where
  //! given, else outward) and the PDE's initial fields. `velocity` has D formulas.
  SurfaceSimulation(PointCloud<D> cloud, SurfaceSettings settings,
                    std::array<PointFormula, D> velocity, std::unique_ptr<SurfacePde<D>> pde,
                    const std::vector<Vec<D>>* reference = nullptr);

  //! One step (§3.7 order), then the observers.
  void step();
  //! Steps until end_time.
  void run();
  bool finished() const { return time_ >= settings_.end_time - 1e-9 * settings_.dt; }

  double time() const { return time_; }
  long step_count() const { return steps_; }
  long point_count() const { return static_cast<long>(cloud_.size()); }
  double last_dt() const { return settings_.dt; }
  const SurfaceSettings& settings() const { return settings_; }
  PointCloud<D>& cloud() { return cloud_; }
  const PointCloud<D>& cloud() const { return cloud_; }
  const NeighbourLists& neighbours() const { return neighbours_; }
  //! S_i^ext: the points within h on other parts (empty lists when the cloud is one part).
  const NeighbourLists& external_neighbours() const { return external_; }
  //! What contact detection found and did at the last step, and in total.
  const ContactReport& last_contact() const { return last_contact_; }
  const ContactReport& contact_total() const { return contact_total_; }
  //! Points removed by the repair after contact: pieces too small to carry a normal, threads,
  //! and with a PDE points at folds no stencil resolves or in bands the velocity crushes
  //! (remove_unresolved).
  long debris_removed() const { return debris_; }
  const SurfaceStencils<D>& stencils() const { return stencils_; }
  SurfacePde<D>* pde() const { return pde_.get(); }
  //! κ per point (eq 37; smoothed by eq 40 when settings say so).
  const std::vector<double>& curvature() const { return curvature_; }
  //! κ̄ of eq 38 over the chamber of point i (each closed surface keeps its own volume under
  //! the averaged flow).
  double mean_curvature_value(std::size_t i) const {
    return kappa_mean_.empty() ? 0.0 : kappa_mean_[cloud_.chamber[i]];
  }
  //! What formulas read at point i, with φ from the PDE's unknown at time t.
  PointValues values_at(std::size_t i, double t) const;
  SparseSystem& system() { return system_; }
  const ManagementReport& management_total() const { return management_total_; }
  const LinearSolveReport& last_solve() const { return last_solve_; }
  void record_solve(const LinearSolveReport& r) { last_solve_ = r; }

  void add_observer(SurfaceObserver<D>* o) { observers_.push_back(o); }
  void remove_observer(SurfaceObserver<D>* o);

 private:
  void advance_one_step();
  void update_geometry(bool keep_side);
  void find_neighbours();
  void average_curvature();
  void resolve_contact();
  bool manage();         //!< point management (§3.4–3.5); true when it changed the cloud
  void surface_rates();  //!< v⁽ⁿ⁺¹⁾ at the points and its surface divergence
  void remove_unresolved();
  void evaluate_velocity(double t, std::vector<Vec<D>>& v) const;
  void check_state() const;
  bool management_due() const;

  PointCloud<D> cloud_;
  SurfaceSettings settings_;
  std::array<PointFormula, D> velocity_;
  std::unique_ptr<SurfacePde<D>> pde_;
  NeighbourSearch<D> search_;
  NeighbourLists neighbours_;
  NeighbourLists external_;
  ContactReport last_contact_, contact_total_;
  long debris_ = 0;
  std::vector<std::uint8_t> short_of_;  //!< scratch of the repairs (points to remove)
  SurfaceStencils<D> stencils_;
  SparseSystem system_;
  std::vector<double> curvature_, divergence_;
  std::vector<double> areas_;              //!< one-ring areas, for κ̄
  std::vector<double> smoothing_weights_;  //!< eq 41, normalised, per neighbour
  std::vector<double> smoothed_;           //!< scratch of the eq 40 passes
  std::vector<Vec<D>> next_velocity_;
  std::vector<Vec<D>> managed_at_;  //!< positions when management last ran
  long managed_generation_ = -1;
  std::vector<double> kappa_mean_;  //!< κ̄ per chamber id
  double time_ = 0.0;
  long steps_ = 0;
  ManagementReport management_total_;
  LinearSolveReport last_solve_;
  std::vector<SurfaceObserver<D>*> observers_;
};

extern template class SurfaceSimulation<2>;
extern template class SurfaceSimulation<3>;

}  // namespace pellicle
