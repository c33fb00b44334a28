#pragma once
//! Particle–grid transfers (DESIGN stages `stencils`, `to_grid`, `to_points`, `remap` and the
//! velocity gradient of `materials`). The interface is chosen once per run; the
//! implementation (transfer_impl.hpp) is compiled per kernel, so the per-point loops are
//! inlined and there is one virtual call per stage, never one per point.

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "pellicle/core/parameters.hpp"
#include "pellicle/core/types.hpp"
#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/materials/material.hpp"
#include "pellicle/mpm/particles.hpp"

namespace pellicle {

//! How grid velocities update point velocities.
enum class VelocityUpdate {
  flip,   //!< v_p += Σ N_i Δv_i (IJNME eq 11)
  pic,    //!< v_p = Σ N_i v_i^L
  blend,  //!< α FLIP + (1 − α) PIC
  apic,   //!< affine PIC (Jiang et al. 2015)
};

struct TransferOptions {
  VelocityUpdate update = VelocityUpdate::flip;
  double flip_fraction = 1.0;  //!< α of the blend
  Kinematics kinematics = Kinematics::plane_strain;
};

//! Points [begin, end) a transfer works on; end < 0 means every point. Contact models move
//! each body in its own grid field, one range per body.
struct PointRange {
  long begin = 0, end = -1;
  long last(long count) const { return end < 0 ? count : end; }
};

//! What to_points also does in its pass over the points, where the scheme allows.
template <int D>
struct PointPassExtras {
  //! MUSL: remap()'s scatter of the updated velocities into the grid's momentum, with the
  //! same result as remap() after to_points.
  bool remap = false;
  //! USL: the velocity gradient of the velocities the points move with, L_p = Σ_i v_i ⊗ ∇N_i
  //! (IJNME eq 13) into gradient[p], and in axisymmetry v_r/r at the new position into
  //! hoop_rate[p]; the same values as point_kinematics() after to_points.
  Mat<D>* gradient = nullptr;
  double* hoop_rate = nullptr;
};

//! ρ ← ρ/(1 + Δt ε̇_v) and V = m/ρ (IJNME eq 17) for point p, with the volumetric rate
//! ε̇_v = tr L (+ v_r/r in axisymmetry). False when ρ became non-positive or non-finite.
template <int D>
inline bool continuity_point(Particles<D>& points, long p, double volumetric_rate, double dt) {
  const double rho = points.density[p] / (1.0 + dt * volumetric_rate);
  points.density[p] = rho;
  points.volume[p] = points.mass[p] / rho;
  return rho > 0.0 && rho < std::numeric_limits<double>::infinity();
}

//! continuity_point() for points [begin, end), from gradient[p − begin] and
//! hoop_rate[p − begin] (null: none). Returns the first point whose density became
//! non-positive or non-finite, or −1.
template <int D>
long continuity_update(Particles<D>& points, const Mat<D>* gradient, const double* hoop_rate,
                       double dt, long begin, long end);

//! Where to_points found the first unusable point, if any.
struct PointFailure {
  long point = -1;
  std::string what;
};

template <int D>
class Transfer {
 public:
  virtual ~Transfer() = default;

  //! Declare the per-point columns the velocity update keeps (APIC: the affine velocity).
  virtual void declare_columns(Particles<D>& points) = 0;

  //! Kinetic energy of the APIC affine velocity field, Σ_p ½ m_p Σ_d D_p,dd |C_p e_d|², with
  //! D_p = Σ_i N_i (x_i − x_p)(x_i − x_p)ᵀ the kernel's inertia at the current position
  //! (Jiang et al. 2015); zero for the other velocity updates.
  virtual double affine_kinetic_energy(const Particles<D>& points, const Grid<D>& grid) const = 0;

  //! Bytes per point the transfer keeps between stages (the stencil anchors).
  virtual std::size_t stencil_bytes() const = 0;

  //! Stage `stencils`: fix this step's stencils (node ids, weights, gradients) at the points'
  //! current positions; every stage of the step uses them, also after to_points has moved
  //! the points. `scatter_ranges`: the point ranges the step's scatters go over, one per
  //! field (empty: all points at once).
  virtual void compute_stencils(const Particles<D>& points, const Grid<D>& grid,
                                const std::vector<PointRange>& scatter_ranges) = 0;

  //! Stage `to_grid`: zero the grid, then scatter mass and momentum (with the APIC affine
  //! term) and, when `forces`, internal and external force:
  //!   f_i = −Σ_p V_p σ_p ∇N_i(x_p) + Σ_p m_p (g + a_body) N_i(x_p)   (IJNME eq 16)
  //! plus, in axisymmetry, the hoop term −Σ_p V_p σ_θθ N_i / r_p on the radial component.
  virtual void to_grid(const Particles<D>& points, const Vec<D>& gravity, Grid<D>& grid,
                       bool forces, PointRange range = {}) = 0;
  //! Scatter only the forces onto a grid whose mass and momentum are already mapped (USF).
  virtual void forces_to_grid(const Particles<D>& points, const Vec<D>& gravity, Grid<D>& grid,
                              PointRange range = {}) = 0;

  //! Stage `to_points`: move points with the Lagrangian grid velocity and update their
  //! velocities (FLIP/PIC/blend/APIC). Returns the largest point speed; a point that leaves
  //! the domain or becomes non-finite is reported in `failure` (the first one found).
  virtual double to_points(Grid<D>& grid, double dt, Particles<D>& points, PointFailure& failure,
                           PointRange range = {}, const PointPassExtras<D>& extras = {}) = 0;

  //! Nodes per point stencil: the kernel's width to the power D.
  virtual int stencil_size() const = 0;
  //! Node layers beyond a box of cells that the stencils of the points inside it reach,
  //! round-off at the box's sides included (a distributed run's window, dist/).
  virtual int node_reach() const = 0;
  //! Node ids and weights N_i(x_p) of points [begin, end) at their current positions,
  //! stencil_size() of each per point, point `begin` first. Computed afresh, not taken from
  //! the step's stencils (those hold the positions at the start of the step), and touching
  //! no state, so threads may call it on disjoint ranges. For output (grid_projection.hpp).
  virtual void node_weights(const Particles<D>& points, const Grid<D>& grid, long begin, long end,
                            long* nodes, double* weights) const = 0;

  //! Grid nodes the points [begin, end) touch (N_i > 0) with this step's stencils, each listed
  //! once, appended to `nodes`.
  virtual void touched_nodes(const Grid<D>& grid, long begin, long end,
                             std::vector<long>& nodes) const = 0;

  //! Stage `remap` (MUSL): the momentum of the updated point velocities on the grid, with
  //! the mass of to_grid; the step then takes the convected velocity p/m (thesis eq 3.24).
  virtual void remap(const Particles<D>& points, Grid<D>& grid, PointRange range = {}) = 0;

  //! Point kinematics of stage `materials` for points [begin, end), from the grid's current
  //! velocity field: the velocity gradient L_p = Σ_i v_i ⊗ ∇N_i(x_p) (IJNME eq 13) into
  //! gradient[p − begin], in axisymmetry the hoop rate v_r/r into hoop_rate[p − begin], and
  //! continuity_update() of the points. Serial: the step calls it for blocks of points from
  //! every thread at once. Returns the first point whose density became non-positive or
  //! non-finite, or −1.
  virtual long point_kinematics(const Grid<D>& grid, double dt, Particles<D>& points, long begin,
                                long end, Mat<D>* gradient, double* hoop_rate) const = 0;
};

//! A kernel known by name.
template <int D>
struct KernelChoice {
  std::string name;
  std::string summary;
  std::unique_ptr<Transfer<D>> (*make)(const TransferOptions& options, double points_per_cell);
  //! APIC works with it (the linear kernel's affine field jumps as points cross cells and
  //! goes unstable at free surfaces: the two-disk test).
  bool offers_apic = true;
  //! Its particle size is h / points_per_cell: every body must use the same points per cell.
  bool one_particle_size = false;
};

//! Registered kernels (transfer.cpp: one line per kernel).
template <int D>
const std::vector<KernelChoice<D>>& kernel_choices();

}  // namespace pellicle
