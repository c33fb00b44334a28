#pragma once
//! Hooks: what acts on the step at its named points without living in it — rigid bodies and
//! other boundary conditions (mpm/boundary/), contact models (mpm/contact/), and the halo
//! exchange and point migration of distributed runs (dist/). A new one is a class here plus
//! its registration; step() does not change.

#include <string>
#include <utility>
#include <vector>

namespace pellicle {

template <int D>
class Simulation;

//! A named array a hook carries from one step to the next (written to checkpoints).
struct HookArray {
  std::string name;
  std::vector<double> values;
  //! One value per node of the grid's storage: a distributed run's checkpoint holds the
  //! whole grid's, from the ranks that own the nodes.
  bool per_node = false;
  bool operator==(const HookArray&) const = default;
};
using HookState = std::vector<HookArray>;

//! Which grid velocities a hook sees after a grid update: the Lagrangian ones after the
//! momentum solve (they move the points), or the convected ones of the MUSL remap (they give
//! the strain rates).
enum class GridPass { lagrangian, convected };

//! Which node sums a scatter has just written (before anything is derived from them).
struct ScatteredFields {
  bool mass = false, momentum = false, force = false;
};

//! An array of `components` doubles per node of the grid's storage, node n at
//! data[n * components].
struct NodeArray {
  double* data;
  int components;
};

//! Carries per-node values from the grid's old storage to its new one when a distributed
//! run's window moves: each node of the new window takes the value the rank that owned it
//! held (zero for a node no rank stored). Collective: every rank calls it alike.
class NodeCarrier {
 public:
  virtual ~NodeCarrier() = default;
  //! `values`: one per node of the old storage (or empty: zero everywhere); on return one per
  //! node of the new storage.
  virtual void carry(std::vector<double>& values) const = 0;
};

template <int D>
class StepHook {
 public:
  virtual ~StepHook() = default;
  //! Right after a scatter onto the grid fields (to_grid, the USF force pass, the MUSL
  //! remap), before velocities or the centre-of-mass field are derived from the sums: where a
  //! distributed run completes the sums of nodes its neighbours share.
  virtual void after_scatter(Simulation<D>&, ScatteredFields) {}
  //! Right after values of this rank's points were summed onto grid nodes outside the step's
  //! scatters (rigid bodies' marks of the nodes they touch, the projections of grid
  //! snapshots), before they are read: where a distributed run completes the sums of nodes
  //! its neighbours share.
  virtual void after_node_sums(const std::vector<NodeArray>& /*arrays*/) {}
  //! Right after points were spread onto a cell field (mpm/cell_field.hpp: a contact
  //! model's colour functions, cell densities), before it is read: where a distributed run
  //! completes the sums of cells its neighbours share.
  virtual void after_cell_spread(Simulation<D>&, std::vector<double>& /*cells*/) {}
  //! After `to_grid`: mass, momentum and forces are on the grid fields.
  virtual void after_to_grid(Simulation<D>&) {}
  //! After the grid velocities were updated (momentum solve, or the MUSL remap).
  virtual void after_grid_update(Simulation<D>&, GridPass, double /*dt*/) {}
  //! After `to_points`: points have their new positions and velocities.
  virtual void after_to_points(Simulation<D>&) {}
  //! After stage `materials`, when no stage of the step reads its stencils any more: where a
  //! distributed run moves points that left their patch to its owner.
  virtual void end_of_step(Simulation<D>&) {}
  //! The grid's storage changed (a distributed run's window moved): node indices a hook
  //! keeps are stale, and values it keeps per node go to the new storage by `carrier`.
  virtual void grid_replaced(const NodeCarrier& /*carrier*/) {}
  //! Figures of the run for summary.json ("figures": name → value), asked once at its end on
  //! every rank of a distributed run (so a hook may reduce them over the ranks).
  virtual void summary_figures(std::vector<std::pair<std::string, double>>& /*out*/) const {}
  //! after_to_points changes point velocities (rigid bodies): the MUSL remap then needs a
  //! pass of its own after it.
  virtual bool sets_point_velocities() const { return false; }
  //! The hook needs each body in its own grid field (contact models).
  virtual bool needs_body_fields() const { return false; }
  //! Hooks that carry state from step to step name it (a checkpoint group); empty: none.
  virtual std::string state_name() const { return {}; }
  virtual HookState save_state() const { return {}; }
  //! Continue from a saved state; arrays the hook does not know are an error it throws.
  virtual void load_state(const HookState&) {}
};

}  // namespace pellicle
