#pragma once
//! Simulation<D>: owns the grid fields, the points, the materials, the transfers and the
//! hooks, and advances them one explicit MPM step at a time (thesis §3 and §5.3; IJNME 1999
//! §2.2). The step is the named stages of DESIGN.md; the update scheme orders stages 3–7.

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "pellicle/core/collective.hpp"
#include "pellicle/core/observer.hpp"
#include "pellicle/core/types.hpp"
#include "pellicle/mpm/cell_density.hpp"
#include "pellicle/mpm/contact/contact_model.hpp"
#include "pellicle/mpm/enclosed_body.hpp"
#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/grid_fields.hpp"
#include "pellicle/mpm/materials/material.hpp"
#include "pellicle/mpm/particles.hpp"
#include "pellicle/mpm/scheme.hpp"
#include "pellicle/mpm/step_hook.hpp"
#include "pellicle/mpm/transfer.hpp"

namespace pellicle {

struct SimulationSettings {
  UpdateScheme scheme = UpdateScheme::musl;
  Kinematics kinematics = Kinematics::plane_strain;
  double fixed_dt = 0.0;      //!< > 0: fixed time step
  double cfl_fraction = 0.0;  //!< > 0: Δt = fraction × h / max(c + |v|), every step
  //! A step whose wave Courant number c Δt / h, or whose transport number |v| Δt / h,
  //! exceeds this stops the run (thesis §8.4: the critical step is h/c to 2h/c).
  double cfl_limit = 1.0;
  double end_time = 1.0;
  //! A run that reaches this many steps before end_time stops (exit 3): a time step that has
  //! collapsed, or one that was far smaller than meant.
  long max_steps = 100000000;
  //! Distributed runs: the patches are split anew when the most points on a rank exceed
  //! the mean by more than this fraction (checked every few steps).
  double rebalance = 0.1;
};

//! Energies and momentum of the whole system (history.csv columns).
template <int D>
struct SystemState {
  //! Kinetic energy includes the APIC affine part; strain is the stored elastic energy;
  //! internal is thermal (gases); gravitational is −Σ m g·x.
  double kinetic = 0.0, strain = 0.0, internal = 0.0, gravitational = 0.0;
  Vec<D> momentum = Vec<D>::Zero();
  double total() const { return kinetic + strain + internal + gravitational; }
};

template <int D>
class Simulation;
//! Called after every step (output writers, probes, progress).
template <int D>
using StepObserver = RunObserver<Simulation<D>>;

template <int D>
class Simulation final : private Stages {
 public:
  //! Declares the columns the materials and the transfer need, and settles the stress of
  //! models whose stress follows from their state. Rigid materials' bodies become a
  //! RigidBodies hook. Throws SetupError for parts that do not fit together.
  Simulation(SimulationSettings settings, Grid<D> grid, Particles<D> points,
             std::vector<std::unique_ptr<Material<D>>> materials,
             std::unique_ptr<Transfer<D>> transfer, Vec<D> gravity);

  //! Advance one step. Throws NumericalError when the state becomes unusable.
  void step();
  //! Step until the end time, or until `max_steps` steps when positive.
  void run(long max_steps = 0);
  bool finished() const;

  //! Use a contact model (each body in its own grid field); without one every body moves
  //! in the single centre-of-mass field. Throws SetupError with the USF scheme.
  void set_contact(std::unique_ptr<ContactModel<D>> model);
  //! The contact model, or null (single centre-of-mass field).
  const ContactModel<D>* contact() const { return contact_; }
  //! Total contact force on each body in the last step; null without a contact model.
  const std::vector<Vec<D>>* contact_forces() const {
    return contact_ ? &contact_->contact_forces() : nullptr;
  }
  //! Add a hook (boundary condition, contact, …) acting at the step's named points.
  void add_hook(std::unique_ptr<StepHook<D>> hook);
  const std::vector<std::unique_ptr<StepHook<D>>>& hooks() const { return hooks_; }
  //! Bodies that fill a membrane's inside (measured in history.csv, enclosed_body.hpp).
  void add_enclosed(EnclosedBody<D> pair) { enclosed_.push_back(std::move(pair)); }
  const std::vector<EnclosedBody<D>>& enclosed() const { return enclosed_; }
  std::vector<std::unique_ptr<StepHook<D>>>& hooks() { return hooks_; }

  //! A distributed run: this simulation holds one rank's points and grid window, and every
  //! quantity of the whole system (time step, energies, largest speeds) is reduced over
  //! `ranks`, which must outlive the simulation. Null: a run on one process.
  void set_collective(const Collective* ranks) { collective_ = ranks; }
  const Collective* collective() const { return collective_; }
  //! Store only a window of the grid (Grid::window): a distributed run's patch and halo.
  //! Hooks carry what they keep per node over with `carrier`.
  void use_grid_window(Grid<D> window, const NodeCarrier& carrier);
  //! Complete node sums just made from this rank's points (the hooks' after_node_sums).
  void complete_node_sums(const std::vector<NodeArray>& arrays) const {
    for (const auto& hook : hooks_) hook->after_node_sums(arrays);
  }
  //! Complete a cell field just spread from this rank's points (the hooks' after_cell_spread).
  void complete_cell_sums(std::vector<double>& cells) {
    for (auto& hook : hooks_) hook->after_cell_spread(*this, cells);
  }
  //! After points were added, removed or reordered (keeping each body contiguous and the
  //! bodies' ranges up to date): rebuild what the step keeps per point range.
  void points_changed();
  //! Settle the stresses that follow from the points' state before the first step: membranes'
  //! from their strains in their frames, fluids' from density and energy. The constructor
  //! does it, except for a distributed run's rank, built with a part of the points (they carry
  //! column_names::body_index): the ranks do it together once their frames see the whole
  //! membranes (distribute). Done once; later calls do nothing.
  void settle_state();

  void add_observer(StepObserver<D>* observer) { observers_.push_back(observer); }
  void remove_observer(StepObserver<D>* observer) { std::erase(observers_, observer); }

  double time() const { return time_; }
  long step_count() const { return step_; }
  long point_count() const { return points_.size(); }
  double last_dt() const { return last_dt_; }
  //! Largest point speed after the last step (part of the next step's CFL signal speed); in
  //! a distributed run, of this rank's points.
  double max_point_speed() const { return max_speed_; }
  //! Wave Courant number Δt max(c)/h of the last step: the stability number of the
  //! Lagrangian step (thesis §8.4), which the point speeds do not enter.
  double cfl_number() const { return cfl_number_; }
  //! The time step the next call of step() would take.
  double planned_dt() const;
  SystemState<D> state() const;
  //! Largest material wave speed c (the CFL number's speed).
  double max_wave_speed() const;
  //! Largest wave speed plus largest point speed: the speed a time step from solver.cfl
  //! is chosen for (a margin over the stability limit, thesis §8.4).
  double max_signal_speed() const;
  //! Rough memory use of points, stencils and grid (for `pellicle check`).
  std::size_t memory_estimate_bytes() const;

  const SimulationSettings& settings() const { return settings_; }
  //! The centre-of-mass grid (every body's in a single-field run).
  const Grid<D>& grid() const { return fields_.centre_of_mass(); }
  GridFields<D>& fields() { return fields_; }
  const GridFields<D>& fields() const { return fields_; }
  const Particles<D>& points() const { return points_; }
  Particles<D>& points() { return points_; }
  Transfer<D>& transfer() { return *transfer_; }
  const Transfer<D>& transfer() const { return *transfer_; }
  const Material<D>& material(int index) const { return *materials_[index]; }
  int material_count() const { return static_cast<int>(materials_.size()); }
  const Vec<D>& gravity() const { return gravity_; }

  //! Continue from a saved state: time, step count and the largest point speed (the points'
  //! and hooks' state are restored by the checkpoint reader).
  void restore_clock(double time, long step, double last_dt, double max_speed);

 private:
  // Stages 3–7 (scheme.hpp), in the order the scheme calls them.
  void to_grid(bool forces) override;
  void grid_velocities() override;
  void forces_to_grid() override;
  void grid(double dt) override;
  void to_points(double dt) override;
  void to_points_and_remap(double dt) override;
  void to_points_and_gradients(double dt) override;
  void materials(double dt) override;

  double time_step();       // stage 1, with the CFL check
  void stencils();          // stage 2
  void observe(double dt);  // stage 8
  //! to_points on every field, each field's pass with `extras`.
  void move_points(double dt, const PointPassExtras<D>& extras);
  //! The continuity update of points [begin, end) from the gradients to_points settled.
  long settled_continuity(double dt, long begin, long end);
  //! The rest of the remap after its scatter: sums completed, velocities p/m, hooks.
  void convected_velocities(double dt);
  void update_frames();
  void settle_cell_densities(double dt);
  //! Each body's check from its blocks' (materials stage), and the fluids' thinning warning.
  void check_materials();
  double time_step(double signal_speed) const;
  //! The point with the largest wave speed (waves) or point speed (otherwise), for failures;
  //! −1 when this process holds no points.
  long fastest_point(bool waves) const;
  [[noreturn]] void fail(long point, const std::string& what) const;
  //! Hooks' after_scatter, then the centre-of-mass sums of per-body fields.
  void scattered(ScatteredFields fields);
  double local_max_wave_speed() const;
  double global_max(double value) const { return collective_ ? collective_->max(value) : value; }

  SimulationSettings settings_;
  GridFields<D> fields_;
  Particles<D> points_;
  std::vector<std::unique_ptr<Material<D>>> materials_;
  std::unique_ptr<Transfer<D>> transfer_;
  std::unique_ptr<Scheme> scheme_;
  std::vector<std::unique_ptr<StepHook<D>>> hooks_;
  std::vector<EnclosedBody<D>> enclosed_;
  ContactModel<D>* contact_ = nullptr;  //!< one of hooks_, or null
  const Collective* collective_ = nullptr;
  Vec<D> gravity_;
  std::vector<StepObserver<D>*> observers_;

  //! Point ranges of fluids whose densities come from cell densities.
  std::vector<std::pair<long, long>> cell_density_ranges_;
  CellDensityWork cell_density_work_;
  Column<Vec<D>> normal_, tangent_;  //!< membrane frames, when a material declares them
  //! Stage `materials` runs over blocks of points of one body each.
  static constexpr long kBlockPoints = 1024;
  struct PointBlock {
    int body;
    long begin, end;
  };
  std::vector<PointBlock> blocks_;
  //! The largest material wave speed of a block's points.
  double wave_speed(const PointBlock& block) const;
  //! Each thread's velocity gradients (and hoop rates) of the block it works on.
  struct BlockScratch {
    std::vector<Mat<D>> gradient;
    std::vector<double> hoop_rate;
  };
  std::vector<BlockScratch> block_scratch_;
  //! Each block's material check, made by the materials stage right after the block's update.
  std::vector<typename Material<D>::PointCheck> block_checks_;
  //! Velocity gradients (and hoop rates) computed before the materials stage: by to_points
  //! (USL, gradients_settled_) or, for fluids with cell densities, by settle_cell_densities.
  std::vector<Mat<D>> settled_gradient_;
  std::vector<double> settled_hoop_rate_;
  bool gradients_settled_ = false;
  bool settled_ = false;  //!< settle_state done
  //! This rank's largest material wave speed, measured by the materials stage for the next
  //! time step; empty when the points changed since (set-up, restore, migration).
  std::optional<double> settled_wave_speed_;
  double time_ = 0.0, last_dt_ = 0.0, cfl_number_ = 0.0, max_speed_ = 0.0;
  long step_ = 0;
  std::set<std::string>
      thinned_;  //!< fluid bodies already warned of thinning below a point per cell
};

extern template class Simulation<2>;
extern template class Simulation<3>;

}  // namespace pellicle
