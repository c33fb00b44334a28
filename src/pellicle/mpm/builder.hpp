#pragma once
//! Assemble a Simulation in C++: the grid, the solver settings, the kernel, materials, bodies
//! and a contact model. The case reader (io/) calls this; so can any program that embeds
//! Pellicle, with no case file:
//!
//!   SimulationBuilder<2> b({0, 0}, {1, 1}, 0.01, faces);
//!   b.settings(settings).kernel("quadratic-bspline", transfer);
//!   const int steel = b.material(std::make_unique<LinearElastic<2>>(...));
//!   BodySetup<2> disk;  disk.name = "disk";  disk.material = steel;  disk.region = ...;
//!   b.body(disk);
//!   auto simulation = b.build();

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pellicle/core/error.hpp"
#include "pellicle/core/types.hpp"
#include "pellicle/geometry/membrane_geometry.hpp"
#include "pellicle/geometry/region.hpp"
#include "pellicle/mpm/simulation.hpp"
#include "pellicle/normals/frame_estimator.hpp"

namespace pellicle {

//! One body: a solid filling a region, or a membrane on a sampled curve or surface.
template <int D>
struct BodySetup {
  std::string name;
  int material = 0;         //!< index returned by SimulationBuilder::material
  int points_per_cell = 2;  //!< solids: per direction
  Vec<D> velocity = Vec<D>::Zero();
  //! Initial velocity field v = velocity + ω × (x − c) + G (x − c); 2D uses ω's z only.
  Vec3 angular_velocity = Vec3::Zero();
  Mat<D> velocity_gradient = Mat<D>::Zero();
  std::optional<Vec<D>> center;            //!< c; default: the body's centre of mass
  Vec<D> external_force = Vec<D>::Zero();  //!< total, spread over the body by mass
  std::optional<Sym<D>> initial_stress, initial_strain;
  //! Points (first, last; indices within the body) that take the initial stress or strain;
  //! default all (the slack of IJNME §3.2 is strain on points 4–9 of a string only).
  std::pair<long, long> initial_points{0, -1};
  std::shared_ptr<const Region<D>> region;  //!< solids: the region the points fill
  //! Instead of `region`: fill the inside of the membrane body of this name (closed, or
  //! closed by the wall and symmetry faces its ends lie on), keeping `gap` cells clear of it;
  //! a gap below 0 means half a point spacing (1 / (2 points_per_cell) cells).
  std::string inside;
  double gap = -1.0;
  //! Membranes: the sampled curve or surface, its thickness and frame estimator.
  std::optional<MembraneGeometry<D>> membrane;
  double thickness = 0.0;
  std::string frames = "connectivity";
  //! How first normal signs are chosen; default: away from the body filling its inside if
  //! there is one (NormalOrientation::away_from_inside), else propagate.
  std::optional<NormalOrientation> orientation;
  std::vector<std::pair<long, double>> point_masses;      //!< (index in body, mass) overrides
  std::vector<std::pair<long, Vec<D>>> point_velocities;  //!< (index in body, velocity) overrides
  std::optional<double> density;  //!< overrides the material's reference density
  //! Instead of a density: the body's total mass (the density follows from its volume, as
  //! the thesis sets its probes' density from their mass, §6.3).
  std::optional<double> total_mass;
  //! From this time on the body carries no stress (a tether cut, thesis §6.3).
  double cut_at = std::numeric_limits<double>::infinity();
  double internal_energy = 0.0;  //!< fluids: initial specific internal energy e
};

//! A problem with one body (body ≥ 0) or with the whole set-up (body = −1).
struct SetupProblem {
  int body = -1;
  std::string key;  //!< the body's key at fault, e.g. "region"
  std::string message;
};

//! The set-up could not be built; every problem found is listed.
class BuildError : public SetupError {
 public:
  explicit BuildError(std::vector<SetupProblem> problems);
  const std::vector<SetupProblem>& problems() const { return problems_; }

 private:
  std::vector<SetupProblem> problems_;
};

//! One body's points as the builder places them, before any is kept, in the order the body is
//! built. A distributed run's rank does not hold them: each walk fills the body's region anew.
template <int D>
struct PlacedBody {
  const std::string& name;
  long count;  //!< its points
  //! visit(x) for the position of each point in turn.
  std::function<void(const std::function<void(const Vec<D>&)>& visit)> walk;
};

//! Which of the placed points this process keeps (a distributed run: those of its patch), a
//! flag per point of each body. Called once, with the whole grid and every body's points.
template <int D>
using PointSelection = std::function<std::vector<std::vector<char>>(
    const Grid<D>& grid, const std::vector<PlacedBody<D>>& bodies)>;

template <int D>
class SimulationBuilder {
 public:
  SimulationBuilder(const Vec<D>& lower, const Vec<D>& upper, double cell,
                    const FaceConditions<D>& faces);

  SimulationBuilder& settings(const SimulationSettings& settings);
  //! A kernel by its registered name (kernel_choices) and the velocity update.
  SimulationBuilder& kernel(const std::string& name, const TransferOptions& options);
  SimulationBuilder& gravity(const Vec<D>& g);
  //! Returns the material's index for BodySetup::material.
  int material(std::unique_ptr<Material<D>> model);
  SimulationBuilder& body(BodySetup<D> body);
  SimulationBuilder& contact(std::unique_ptr<ContactModel<D>> model);
  //! A boundary condition or other hook (mpm/boundary/), applied in the order added.
  SimulationBuilder& hook(std::unique_ptr<StepHook<D>> hook);
  //! Keep only the points `select` chooses: a distributed run's rank builds its patch's. What
  //! belongs to a whole body (its mass and centre, a total_mass's density, point indices of
  //! overrides and initial states) is still the whole body's as built; each kept point
  //! carries its index in its body (column_names::body_index) and each body its built count
  //! (BodyInfo::built). The simulation's grid then has no node storage and its state is not
  //! yet settled: the caller gives it its window (Simulation::use_grid_window) and settles
  //! it (Simulation::settle_state) before the first step, as dist/distribute does.
  SimulationBuilder& select_points(PointSelection<D> select);

  //! Fill the bodies with points and assemble the simulation (the builder is spent). Throws
  //! BuildError listing every problem (a region without points inside the grid, a membrane
  //! point outside it, a point index a body does not have, a kernel or combination that
  //! does not exist) and SetupError for parts that do not work together.
  std::unique_ptr<Simulation<D>> build();

 private:
  Vec<D> lower_, upper_;
  double cell_;
  FaceConditions<D> faces_;
  SimulationSettings settings_;
  std::string kernel_ = "linear";
  TransferOptions transfer_;
  Vec<D> gravity_ = Vec<D>::Zero();
  std::vector<std::unique_ptr<Material<D>>> materials_;
  std::vector<BodySetup<D>> bodies_;
  std::unique_ptr<ContactModel<D>> contact_;
  std::vector<std::unique_ptr<StepHook<D>>> hooks_;
  PointSelection<D> select_;
};

//! Volume a point stands for: its sub-cell (per unit depth in 2D; × 2πr in axisymmetry).
template <int D>
double point_volume(double cell, int points_per_cell, Kinematics kinematics, const Vec<D>& x);

extern template class SimulationBuilder<2>;
extern template class SimulationBuilder<3>;

}  // namespace pellicle
