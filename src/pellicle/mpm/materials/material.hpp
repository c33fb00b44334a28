#pragma once
//! The constitutive-model interface. A material updates all of its points in one call
//! (never one virtual call per point), from the velocity gradient the grid gives them.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pellicle/core/parameters.hpp"
#include "pellicle/core/types.hpp"
#include "pellicle/mpm/particles.hpp"

namespace pellicle {

//! How a 2D run interprets the third direction; 3D runs use `solid`.
enum class Kinematics { plane_strain, plane_stress, axisymmetric, solid };

//! Values a stage computed for a run of points: point p's is data[p − first].
template <class T>
struct BlockValues {
  const T* data = nullptr;
  long first = 0;
  BlockValues() = default;
  BlockValues(const T* values, long first_point) : data(values), first(first_point) {}
  //! Values of every point, point 0 first (an empty vector: none).
  BlockValues(const std::vector<T>& all) : data(all.data()) {}  // NOLINT: implicit on purpose
  const T& operator[](long p) const { return data[p - first]; }
};

//! What a material needs for one step over the points [begin, end).
template <int D>
struct MaterialStep {
  Particles<D>& points;  //!< membrane points carry their current frames (normal, tangent)
  BlockValues<Mat<D>> velocity_gradient;  //!< L_ij = ∂v_i/∂x_j of points [begin, end)
  BlockValues<double> hoop_rate;          //!< v_r/r (axisymmetric), else none
  double dt;
  long begin, end;
  double cell = 0.0;  //!< grid cell size h (artificial viscosity length, thesis eq 4.12)
};

//! The state a body's points start from (case keys initial_strain, initial_stress,
//! internal_energy).
template <int D>
struct InitialState {
  Sym<D> strain = Sym<D>::Zero();
  std::optional<Sym<D>> stress;  //!< given directly; otherwise the stress of `strain`
  double internal_energy = 0.0;  //!< specific internal energy e (fluids)
};

//! A quantity a material computes for snapshots from its columns (one value per point).
struct SnapshotField {
  std::string name;
  int components = 1;
};

template <int D>
class Material {
 public:
  explicit Material(Kinematics kinematics) : kinematics_(kinematics) {}
  virtual ~Material() = default;

  //! Declare the per-point columns the model reads and writes (point_columns.hpp) and keep
  //! their handles. Called once, before points are added or a run starts; a column another
  //! model declared under the same name is shared.
  virtual void declare_columns(Particles<D>& points);
  //! Set the starting state of points [begin, end) of a body: the stress (given, or from the
  //! strain) and the declared columns. Models whose stress follows from their state
  //! (membranes, fluids) settle it at the first zero step instead.
  virtual void initialise(Particles<D>& points, long begin, long end,
                          const InitialState<D>& state) const;

  //! Stress and strain update of the points over one step (objective rate, see each model).
  //! Serial: the step calls it for blocks of points from every thread at once, so it touches
  //! only the points [begin, end) and nothing shared.
  virtual void update(const MaterialStep<D>& step) const = 0;
  //! Largest signal speed over the points on cells of size `cell`, for the CFL time step
  //! (IJNME eq 19): the elastic wave speed for solids; for fluids the sound speed raised by
  //! the viscous terms (docs/theory/gas.md). Serial, like update: the step calls it for each
  //! block of points right after updating them, while they are in the cache.
  virtual double max_signal_speed(const Particles<D>& points, long begin, long end,
                                  double cell) const = 0;
  //! Stored (recoverable) elastic energy of the points.
  virtual double strain_energy(const Particles<D>& points, long begin, long end) const = 0;
  //! Internal (thermal and compression) energy Σ m e of fluid points; 0 for solids.
  virtual double internal_energy(const Particles<D>&, long, long) const { return 0.0; }
  //! Stress produced by a given strain from the unstressed state (initial strain input).
  virtual Sym<D> stress_from_strain(const Sym<D>& strain) const = 0;
  //! Reference mass density of the material.
  virtual double density() const = 0;
  //! Membrane models need a body of membrane points with frames; solids fill regions.
  virtual bool is_membrane() const { return false; }
  //! Rigid bodies move with a prescribed velocity and impose it on the grid nodes they touch.
  virtual bool is_rigid() const { return false; }
  //! Fluids (gas, liquids) carry a specific internal energy and report pressure and volume.
  virtual bool is_fluid() const { return false; }
  //! Fluids may take their point densities from cell densities (thesis eq 4.6) instead of
  //! the continuity equation.
  virtual bool density_from_cells() const { return false; }
  //! The state of points [begin, end) the step must check: the first point the model cannot
  //! continue from, and how thin a fluid has become. Serial, like update: the materials stage
  //! calls it for each block right after the block's update.
  struct PointCheck {
    long invalid = -1;  //!< first point the model cannot continue from, or −1
    std::string why;    //!< what is wrong with it
    //! Fluids: the point farthest from its neighbours along its most stretched direction, and
    //! that spacing in cells; above 1 the gas has fewer than one point per cell that way and
    //! is no longer resolved (gaps open between the points).
    long thinnest = -1;
    double spacing = 0.0;
  };
  virtual PointCheck check_points(const Particles<D>&, long /*begin*/, long /*end*/,
                                  double /*cell*/) const {
    return {};
  }
  //! The stress follows from the points' state (frames, density, energy), not from the
  //! stress before: it is settled by a zero step before the first step.
  virtual bool stress_from_state() const { return false; }

  //! Per-body history.csv columns of this model (`<body>.<name>`). Their values come from
  //! sums over the body's points, so that a body spread over the ranks of a distributed run
  //! adds its ranks' sums: history_sums appends the sums of points [begin, end),
  //! history_from_sums turns a whole body's sums into the columns' values, in order.
  virtual std::vector<std::string> history_names() const { return {}; }
  virtual void history_sums(const Particles<D>&, long /*begin*/, long /*end*/,
                            std::vector<double>& /*sums*/) const {}
  virtual void history_from_sums(const double* /*sums*/, std::vector<double>& /*out*/) const {}
  //! The columns' values of the points [begin, end) of one process.
  void history_values(const Particles<D>& points, long begin, long end,
                      std::vector<double>& out) const {
    std::vector<double> sums;
    history_sums(points, begin, end, sums);
    history_from_sums(sums.data(), out);
  }
  //! Quantities computed for snapshots from the model's columns, and their values for
  //! points [begin, end) written to `out` (components per point, point `begin` first).
  virtual std::vector<SnapshotField> snapshot_fields() const { return {}; }
  virtual void snapshot_values(int /*field*/, const Particles<D>&, long, long, double*) const {}
  //! A warning for `pellicle check` when this model's points are moved by FLIP; empty when
  //! FLIP suits it.
  virtual std::string flip_caution() const { return {}; }

  Kinematics kinematics() const { return kinematics_; }

 protected:
  //! The accumulated small strain Σ Δε, shared by the models that keep it; declared by
  //! declare_columns' default.
  Column<Sym<D>> strain_;

 private:
  Kinematics kinematics_;
};

//! Builds one material from its parameter table.
template <int D>
using MaterialFactory = std::unique_ptr<Material<D>> (*)(ParameterReader& parameters,
                                                         Kinematics kinematics);

//! Known models by name (see registry.cpp: one line per model).
template <int D>
struct MaterialModel {
  std::string name;
  std::string summary;
  MaterialFactory<D> make;
};

template <int D>
const std::vector<MaterialModel<D>>& material_models();

template <int D>
void Material<D>::declare_columns(Particles<D>& points) {
  strain_ = points.template declare<Sym<D>>({column_names::strain, "1", true, true});
}

template <int D>
void Material<D>::initialise(Particles<D>& points, long begin, long end,
                             const InitialState<D>& state) const {
  const Sym<D> stress = state.stress ? *state.stress : stress_from_strain(state.strain);
  for (long p = begin; p < end; ++p) {
    points.stress[p] = stress;
    if (strain_.valid()) points[strain_][p] = state.strain;
  }
}

}  // namespace pellicle
