#pragma once
//! The background Cartesian grid: node arrays (structure of arrays), index math and the
//! boundary conditions on its faces. All index arithmetic lives here.

#include <omp.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "pellicle/core/types.hpp"

namespace pellicle {

//! Condition on a grid face: nodes on the face are constrained, ghost nodes beyond it mirror
//! the interior (see Grid::fold).
enum class FaceCondition : std::uint8_t {
  free,   //!< no constraint
  slip,   //!< zero normal velocity (symmetry plane, frictionless wall, axisymmetric axis)
  fixed,  //!< zero velocity
};

//! Face order: x-min, x-max, y-min, y-max[, z-min, z-max].
template <int D>
using FaceConditions = std::array<FaceCondition, 2 * D>;

//! Nodes first..last of one row of the grid's storage (a row: the nodes along axis 0 at fixed
//! higher indices), as offsets within the row; empty when last < first.
struct NodeSpan {
  int first = std::numeric_limits<int>::max(), last = std::numeric_limits<int>::min();
  bool empty() const { return last < first; }
  long size() const { return empty() ? 0 : long{last} - first + 1; }
  //! Grow to the smallest span holding this one and nodes a..b.
  void add(int a, int b) { first = std::min(first, a), last = std::max(last, b); }
  bool operator==(const NodeSpan&) const = default;
};

template <int D>
class Grid {
 public:
  //! Ghost node layers outside the domain, enough for the widest kernel (cubic B-spline).
  static constexpr int kGhost = 2;

  Grid(const Vec<D>& lower, const Vec<D>& upper, double cell, const FaceConditions<D>& faces);
  //! The same grid's shape, faces and node numbering without its node storage: what a rank of
  //! a distributed run holds until it takes the window it stores (window()). Only geometry
  //! and node indices may be asked of it.
  static Grid without_storage(const Vec<D>& lower, const Vec<D>& upper, double cell,
                              const FaceConditions<D>& faces);

  //! The part of this grid a rank of a distributed run stores: nodes `first` to `last`
  //! (inclusive, in grid index space, ghosts included). It keeps the whole grid's origin,
  //! domain and faces, and takes node indices in the whole grid's index space, so a point's
  //! cell units and kernel weights are bitwise those of the whole grid; only the storage and
  //! flat indices are local. The face conditions apply where the window reaches a face. A
  //! window's window may lie anywhere in the whole grid (a rank's patch moved). The rank
  //! owns nodes `owned_first` to `owned_last` (within the window): each node of the whole grid
  //! is owned by one rank, which alone counts it in sums over the whole grid.
  Grid window(const IVec<D>& first, const IVec<D>& last, const IVec<D>& owned_first,
              const IVec<D>& owned_last) const;
  //! True when this storage counts node `node` in sums over the whole grid: every node of a
  //! whole grid, the owned nodes of a window.
  bool owns(long node) const {
    const IVec<D> index = unflatten(node);
    return (index.array() >= owned_first_.array()).all() &&
           (index.array() <= owned_last_.array()).all();
  }

  double cell() const { return h_; }
  double inverse_cell() const { return inv_h_; }  //!< 1/h
  const Vec<D>& lower() const { return lower_; }
  const Vec<D>& upper() const { return upper_; }
  const IVec<D>& cells() const { return cells_; }  //!< cells across the domain per axis
  const IVec<D>& nodes() const { return nodes_; }  //!< nodes per axis stored (ghosts included)
  long node_count() const { return node_count_; }
  //! Grid index of the first stored node (nonzero in a window).
  const IVec<D>& first() const { return first_; }
  //! The nodes this storage counts in sums over the whole grid (owns()), as a box.
  const IVec<D>& owned_first() const { return owned_first_; }
  const IVec<D>& owned_last() const { return owned_last_; }
  //! Position of node (i, j[, k]) given in grid index space (ghosts included).
  Vec<D> node_position(const IVec<D>& index) const {
    return origin_ + h_ * index.template cast<double>();
  }
  Vec<D> node_position(long node) const { return node_position(unflatten(node)); }
  //! Grid coordinates ξ = (x − origin)/h used by the kernels.
  Vec<D> to_cell_units(const Vec<D>& x) const { return (x - origin_) * inv_h_; }
  //! Storage index of the node with grid index `index`.
  long flatten(const IVec<D>& index) const {
    long n = index[D - 1] - first_[D - 1];
    for (int d = D - 2; d >= 0; --d) n = n * nodes_[d] + (index[d] - first_[d]);
    return n;
  }
  //! Grid index of the node stored at `node`.
  IVec<D> unflatten(long node) const {
    IVec<D> index;
    for (int d = 0; d < D; ++d) {
      index[d] = static_cast<int>(node % nodes_[d]) + first_[d];
      node /= nodes_[d];
    }
    return index;
  }
  //! Flat-index distance between neighbouring nodes along each axis.
  const std::array<long, D>& strides() const { return strides_; }
  //! True when x lies in the closed domain box.
  bool contains(const Vec<D>& x) const {
    return (x.array() >= lower_.array()).all() && (x.array() <= upper_.array()).all();
  }
  const FaceConditions<D>& faces() const { return faces_; }
  //! A point just beyond a wall or symmetry face (fixed or slip), by no more than round-off
  //! (1e-6 of a cell), is put back on the face; true when x is then inside the domain.
  bool return_to_face(Vec<D>& x) const;

  //! Momentum-form explicit update (IJNME eqs 9, 11): velocity = (p + Δt f)/m and the
  //! change over the step, both with the face conditions applied and the ghosts mirrored.
  //! Nodes without mass get zero.
  void integrate(double dt);
  //! velocity = p/m with the face conditions (convected velocity, thesis eq 3.24).
  void velocities_from_momentum();

  //! Add what points scattered onto ghost nodes beyond constrained faces to the mirrored
  //! interior nodes (mass as it is, vectors reflected) and clear the ghosts. The ghost
  //! degrees of freedom are slaved, v_ghost = R v_image, so their mass, momentum and force
  //! belong to the image node (Rᵀ of the constraint; R is its own transpose).
  void fold(std::vector<double>& field) const;
  void fold(std::vector<Vec<D>>& field) const;
  //! Set ghost-node values beyond constrained faces from their images: v_ghost = R v_image.
  void mirror(std::vector<Vec<D>>& field) const;

  //! Nodes that take a prescribed velocity (rigid bodies, boundary conditions), added every
  //! step after `to_grid` clears them, and applied by integrate() and
  //! velocities_from_momentum(). A node prescribed twice takes the later velocity.
  void prescribe(const std::pair<long, Vec<D>>* first, const std::pair<long, Vec<D>>* last);
  void prescribe(const std::vector<std::pair<long, Vec<D>>>& nodes) {
    prescribe(nodes.data(), nodes.data() + nodes.size());
  }
  void clear_prescribed() { prescribed_.clear(); }

  //! Live nodes (docs/theory/performance.md, "Live nodes"): per row of the storage one span,
  //! outside which every node field is zero, so the passes over whole fields visit the spans
  //! only. Each step's first scatter restarts them from the spans its points' stencils reach;
  //! whatever else writes a node marks it first (prescribe() does). The spans are closed under
  //! the ghost mirrors, so fold() and mirror() stay inside them. A new grid is live everywhere.
  //!
  //! Zero mass, momentum and force on the live nodes, and the velocities on those `next` does
  //! not hold; then `next` (one span per row; any other size: every node) is the live set.
  void restart_live(const std::vector<NodeSpan>& next);
  //! Add nodes to the live set (their fields are zero until written).
  void mark_live(const long* first, const long* last);
  const std::vector<NodeSpan>& live() const { return live_; }
  bool is_live(long node) const {
    const NodeSpan& span = live_[node / nodes_[0]];
    const long x = node % nodes_[0];
    return x >= span.first && x <= span.last;
  }
  long row_count() const { return node_count_ / nodes_[0]; }
  //! Stored row holding the nodes (·, j[, k]) given as grid indices of the higher axes.
  long row_of(const int* index) const {
    long r = index[D - 1] - first_[D - 1];
    for (int d = D - 2; d >= 1; --d) r = r * nodes_[d] + (index[d] - first_[d]);
    return r;
  }
  //! f(node) for every live node, in parallel: each thread a run of rows of about equal
  //! live node counts. Call outside a parallel region.
  template <class F>
  void for_each_live(F&& f) const {
#pragma omp parallel
    for_each_live_of_thread(f);
  }
  //! f(node) for this thread's share of the live nodes; every thread of a parallel region
  //! calls it (a worksharing loop over the live nodes).
  template <class F>
  void for_each_live_of_thread(F&& f) const {
    const long width = nodes_[0];
    const auto [r0, r1] = live_rows_of_thread();
    for (long r = r0; r < r1; ++r) {
      const long begin = r * width + live_[r].first, end = r * width + live_[r].last;
      for (long n = begin; n <= end; ++n) f(n);
    }
  }
  //! Zero a node field on the live nodes (outside them it is zero already).
  template <class T>
  void zero_live(std::vector<T>& field) const {
    for_each_live([&](long n) {
      if constexpr (std::is_same_v<T, double>)
        field[n] = 0.0;
      else
        field[n].setZero();
    });
  }

  //! Zero the constrained components of a nodal vector field (velocity, momentum, force).
  //! Outside the live nodes they are zero already.
  void constrain(std::vector<Vec<D>>& field) const {
    for (const auto& c : live_constraints_)
      for (int d = 0; d < D; ++d)
        if (c.mask & (1u << d)) field[c.node][d] = 0.0;
  }

  // Node fields.
  std::vector<double> mass;             //!< lumped mass m_i = Σ_p m_p N_i(x_p) (IJNME eq 7)
  std::vector<Vec<D>> momentum;         //!< p_i = Σ_p m_p v_p N_i(x_p) (eq 10)
  std::vector<Vec<D>> force;            //!< internal plus external force (eq 16)
  std::vector<Vec<D>> velocity;         //!< Lagrangian v_i^L, then the convected velocity
  std::vector<Vec<D>> velocity_change;  //!< v_i^L − v_i^k over the step (FLIP increment)

 private:
  struct Constraint {
    long node;
    unsigned mask;  //!< bit d set: component d is held at zero
  };
  struct Mirror {
    long ghost, image;
    unsigned flips;  //!< bit d set: component d changes sign between ghost and image
  };
  static Vec<D> reflect(const Vec<D>& v, unsigned flips) {
    Vec<D> r = v;
    for (int d = 0; d < D; ++d)
      if (flips & (1u << d)) r[d] = -r[d];
    return r;
  }
  //! The shape alone (without_storage, window): cells, origin and spacing.
  struct Shape {};
  Grid(const Vec<D>& lower, const Vec<D>& upper, double cell, const FaceConditions<D>& faces,
       Shape);
  //! Node numbering of the nodes first_ to first_ + nodes_ − 1 (all owned).
  void set_extent(const IVec<D>& first, const IVec<D>& count);
  //! Their numbering, storage, face constraints and mirrors.
  void allocate(const IVec<D>& first, const IVec<D>& count);

  Vec<D> lower_, upper_, origin_;
  double h_, inv_h_;
  IVec<D> cells_, nodes_, first_ = IVec<D>::Zero(), owned_first_, owned_last_;
  std::array<long, D> strides_{};
  long node_count_ = 0;
  FaceConditions<D> faces_;
  std::vector<Constraint> constraints_;
  std::vector<Mirror> mirrors_;  //!< in axis order; mirror() walks them backwards
  //! mirrors_ in groups of one face each: [group_ends_[g − 1], group_ends_[g]). Within a
  //! group every ghost and every image appears once and no image is a ghost, so a group's
  //! pairs may be folded or mirrored in any order; the groups keep theirs (corner ghosts
  //! reach the interior through the faces of two axes).
  std::vector<long> group_ends_;
  //! The constraints on live nodes, which constrain() visits, and the pairs of mirrors_ whose
  //! nodes are live, in the same groups, which fold() and mirror() visit.
  std::vector<Constraint> live_constraints_;
  std::vector<Mirror> live_mirrors_;
  std::vector<long> live_group_ends_;
  void select_live_boundary();
  //! f(begin, end) for each group of live_mirrors_, in order or (Backwards) in reverse order.
  template <bool Backwards = false, class F>
  void for_each_mirror_group(F&& f) const;
  std::vector<std::pair<long, Vec<D>>> prescribed_;
  std::vector<NodeSpan> live_;    //!< one per row
  std::vector<long> live_parts_;  //!< threads' row runs: [live_parts_[t], live_parts_[t + 1])
  //! This thread's rows [first, last) of the live set: shared by live node counts.
  std::pair<long, long> live_rows_of_thread() const {
    const int t = omp_get_thread_num(), threads = omp_get_num_threads();
    const long rows = row_count();
    if (static_cast<int>(live_parts_.size()) == threads + 1)
      return {live_parts_[t], live_parts_[t + 1]};
    return {rows * t / threads, rows * (t + 1) / threads};
  }
  //! Grow the live spans until every mirror pair has both nodes live or neither, then share
  //! the rows out among the threads.
  void close_live();
  void add_live(long node) {
    const int x = static_cast<int>(node % nodes_[0]);
    live_[node / nodes_[0]].add(x, x);
  }
};

extern template class Grid<2>;
extern template class Grid<3>;

}  // namespace pellicle
