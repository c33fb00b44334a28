#pragma once
//! Kernel-templated implementation of the transfers. Included only by the per-kernel
//! instantiation files (transfer_*.cpp), so the heavy inlining is compiled once per kernel.

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "pellicle/core/ordered_sum.hpp"
#include "pellicle/mpm/scatter_buffers.hpp"
#include "pellicle/mpm/shape/kernels.hpp"
#include "pellicle/mpm/shape/stencil.hpp"
#include "pellicle/mpm/transfer.hpp"

namespace pellicle {

template <int D, class Kernel>
class TransferImpl final : public Transfer<D> {
 public:
  TransferImpl(const TransferOptions& options, Kernel kernel)
      : options_(options), kernel_(kernel) {}

  void declare_columns(Particles<D>& points) override {
    if (!apic()) return;
    affine_ = points.template declare<Mat<D>>({"affine", "1/s", false, true});
    // With a thermal model present, the kinetic energy the transfers dissipate becomes heat.
    if (points.columns.template find<double>(column_names::internal_energy).valid())
      heat_ = points.template declare<double>({column_names::transfer_heat, "J/kg", false, true});
  }

  double affine_kinetic_energy(const Particles<D>& points, const Grid<D>& grid) const override {
    if (!apic()) return 0.0;
    const long n = points.size();
    const auto& affine = points[affine_];
    const double h = grid.cell();
    return ordered_sum(0, n, [&](long p) {
      const Vec<D> xi = grid.to_cell_units(points.position[p]);
      double e = 0.0;
      for (int d = 0; d < D; ++d) {
        double w[Kernel::width], dw[Kernel::width];
        const int first = kernel_.fill(xi[d], w, dw);
        double inertia = 0.0;  // D_dd / h²: tensor-product kernels give a diagonal D
        for (int a = 0; a < Kernel::width; ++a)
          inertia += w[a] * (first + a - xi[d]) * (first + a - xi[d]);
        e += inertia * affine[p].col(d).squaredNorm();
      }
      return 0.5 * points.mass[p] * h * h * e;
    });
  }

  std::size_t stencil_bytes() const override { return sizeof(StencilAnchor<D>); }

  void compute_stencils(const Particles<D>& points, const Grid<D>& grid,
                        const std::vector<PointRange>& scatter_ranges) override {
    const long n = points.size();
    anchors_.resize(n);
    // The anchors change, and with them what every range's stencils touch. The points are
    // anchored range by range (a field's points, or all points at once when the ranges do
    // not tile them), each with the static schedule its scatters use, so that each thread
    // finds its share's nodes as it goes (thread_target) and each range its own live nodes.
    range_nodes_.clear();
    bool tiled = !scatter_ranges.empty();
    long next = 0;
    for (const PointRange& range : scatter_ranges) {
      tiled = tiled && range.begin == next;
      next = range.last(n);
    }
    if (tiled && next == n) {
      for (const PointRange& range : scatter_ranges) range_nodes(range.begin, range.last(n));
    } else {
      range_nodes(0, n);
    }
    const int ranges = static_cast<int>(range_nodes_.size());
    const long rows = grid.row_count();
    thread_spans_.resize(static_cast<std::size_t>(omp_get_max_threads()) * ranges);
    int team = 1;
    bool inside = true;
#pragma omp parallel reduction(&& : inside)
    {
      const int t = omp_get_thread_num(), threads = omp_get_num_threads();
      if (t == 0) team = threads;
      for (int r = 0; r < ranges; ++r) {
        RangeNodes& nodes = range_nodes_[r];
        // The live nodes (Grid::restart_live): per first row of the stencils, the span they
        // reach.
        std::vector<NodeSpan>& spans = thread_spans_[t * ranges + r];
        spans.assign(rows, NodeSpan{});
        RowReach reach;
        long lo = std::numeric_limits<long>::max(), hi = -1;
#pragma omp for schedule(static) nowait
        for (long p = nodes.begin; p < nodes.end; ++p) {
          // The positions, last written a whole step ago, are the stream this pass waits on.
          __builtin_prefetch(points.position.data() + p + 32);
          anchors_[p] = stencil_anchor(kernel_, grid, points.position[p]);
          if (threads > 1) extend_node_range(grid, anchors_[p], lo, hi);
          reach.add(grid, anchors_[p], spans);
        }
        reach.flush(grid, spans);
        inside = inside && reach.inside;
        if (threads > 1) {
          nodes.per_thread[t] = {lo, hi};
          if (t == 0) nodes.threads = threads;
        }
      }
    }
    // A point outside the storage is stopped by the step's checks; until then every node is
    // live (an empty list).
    all_spans_.clear();
    if (!inside) return;
    for (int r = 0; r < ranges; ++r) {
      std::vector<NodeSpan>& spans = range_nodes_[r].spans;
      spans = thread_spans_[r];
      for (int t = 1; t < team; ++t)
        for (long row = 0; row < rows; ++row)
          spans[row].add(thread_spans_[t * ranges + r][row].first,
                         thread_spans_[t * ranges + r][row].last);
      stencil_spans(grid, spans);
      if (r == 0) {
        all_spans_ = spans;
      } else {
        for (long row = 0; row < rows; ++row)
          all_spans_[row].add(spans[row].first, spans[row].last);
      }
    }
  }

  void to_grid(const Particles<D>& points, const Vec<D>& gravity, Grid<D>& grid, bool forces,
               PointRange range) override {
    grid.restart_live(live_spans(range.begin, range.last(points.size())));
    if (apic()) {
      if (forces)
        scatter<true, true, true>(points, gravity, grid, range);
      else
        scatter<true, false, true>(points, gravity, grid, range);
    } else {
      if (forces)
        scatter<true, true, false>(points, gravity, grid, range);
      else
        scatter<true, false, false>(points, gravity, grid, range);
    }
  }

  void forces_to_grid(const Particles<D>& points, const Vec<D>& gravity, Grid<D>& grid,
                      PointRange range) override {
    grid.zero_live(grid.force);
    scatter<false, true, false>(points, gravity, grid, range);
  }

  double to_points(Grid<D>& grid, double dt, Particles<D>& points, PointFailure& failure,
                   PointRange range, const PointPassExtras<D>& extras) override {
    if (extras.gradient) return to_points_with<true>(grid, dt, points, failure, range, extras);
    return to_points_with<false>(grid, dt, points, failure, range, extras);
  }

  int stencil_size() const override {
    return Stencil<D, Kernel>::size;
  }

  int node_reach() const override {
    // Points of cell [c, c + 1) with c = 100, moved by far more than round-off either way;
    // first() does not decrease with ξ, so the ends give the reach.
    const int below = 100 - kernel_.first(100.0 - 1e-9);
    const int above = kernel_.first(101.0 + 1e-9) + Kernel::width - 1 - 101;
    return std::max({below, above, 0});
  }

  void node_weights(const Particles<D>& points, const Grid<D>& grid, long begin, long end,
                    long* nodes, double* weights) const override {
    for (long p = begin; p < end; ++p) {
      Stencil<D, Kernel> s;
      compute_stencil(kernel_, grid, points.position[p], s);
      for_each_node(s, grid.strides(), [&](long node, double N, const Vec<D>&, const IVec<D>&) {
        *nodes++ = node;
        *weights++ = N;
      });
    }
  }

  void touched_nodes(const Grid<D>& grid, long begin, long end,
                     std::vector<long>& nodes) const override {
    const std::size_t first = nodes.size();
    for (long p = begin; p < end; ++p)
      for_each_node(stencil(grid, p), grid.strides(),
                    [&](long node, double N, const Vec<D>&, const IVec<D>&) {
                      if (N > 0.0) nodes.push_back(node);
                    });
    std::sort(nodes.begin() + first, nodes.end());
    nodes.erase(std::unique(nodes.begin() + first, nodes.end()), nodes.end());
  }

  void remap(const Particles<D>& points, Grid<D>& grid, PointRange range) override {
    grid.zero_live(grid.momentum);
    if (apic())
      scatter<false, false, true, true>(points, Vec<D>::Zero(), grid, range);
    else
      scatter<false, false, false, true>(points, Vec<D>::Zero(), grid, range);
  }

  long point_kinematics(const Grid<D>& grid, double dt, Particles<D>& points, long begin, long end,
                        Mat<D>* gradient, double* hoop_rate) const override {
    const auto& strides = grid.strides();
    const bool axisymmetric = options_.kinematics == Kinematics::axisymmetric;
    long first_bad = -1;
    constexpr int W = Kernel::width;
    for (long p = begin; p < end; ++p) {
      const Stencil<D, Kernel> s = stencil(grid, p);
      // Row sums (stencil.hpp): L's column 0 from Σ_rows weight · block, the others from
      // Σ_rows grad_e · block.
      RowSums<D, W> rows;
      sum_rows<false, true>(s, strides, grid.velocity, rows);
      double L[D][D];  // L[e]: column e
      contract_block<D, W>(rows.value, s.dw[0], L[0]);
      for (int e = 1; e < D; ++e) contract_block<D, W>(rows.grad[e], s.w[0], L[e]);
      store_gradient(L, gradient[p - begin]);
      double volumetric = 0.0;
      for (int i = 0; i < D; ++i) volumetric += L[i][i];
      if (axisymmetric) {
        double v_radial = 0.0;  // Σ N_i v_i,r
        for (int a = 0; a < W; ++a) v_radial += s.w[0][a] * rows.value[a * D];
        hoop_rate[p - begin] = v_radial / points.position[p][0];
        volumetric += hoop_rate[p - begin];
      }
      // In the same loop, so the divisions overlap the next point's sums.
      if (!continuity_point(points, p, volumetric, dt) && first_bad < 0) first_bad = p;
    }
    return first_bad;
  }

 private:
  bool apic() const {
    return options_.update == VelocityUpdate::apic;
  }

  //! to_points; with `Heat` (APIC only) also the kinetic energy per unit mass the point's two
  //! transfers removed this step, ½ (r_in + r_out) (docs/theory/gas.md):
  //!   r_in  = Σ_i N_i |v_p + C_p (x_i − x_p) − ṽ_i|²   (to_grid; ṽ_i the mapped velocity)
  //!   r_out = Σ_i N_i |v_i|² − |v_p'|² − Σ_d D_dd |C_p' e_d|²   (to_points; v_i updated)
  //! (r_out from weighted sums: Σ N_i = 1, Σ N_i (x_i − x_p) = 0). With the B-splines' C' = B D⁻¹,
  //! r_out = Σ_i N_i |v_i − v_p' − C_p'(x_i − x_p)|² ≥ 0; the gradient form's C' can give
  //! energy back (r_out < 0).
  template <bool Gradient>
  double to_points_with(Grid<D>& grid, double dt, Particles<D>& points, PointFailure& failure,
                        PointRange range, const PointPassExtras<D>& extras) {
    if (heat_.valid())
      return move_points<true, true, Gradient>(grid, dt, points, failure, range, extras);
    return apic() ? move_points<true, false, Gradient>(grid, dt, points, failure, range, extras)
                  : move_points<false, false, Gradient>(grid, dt, points, failure, range, extras);
  }

  template <bool Apic, bool Heat, bool Gradient>
  double move_points(Grid<D>& grid, double dt, Particles<D>& points, PointFailure& failure,
                     PointRange range, const PointPassExtras<D>& extras) {
    static_assert(Apic || !Heat);
    constexpr int W = Kernel::width;
    constexpr bool bspline_moment = Kernel::apic_inertia > 0.0;
    constexpr bool with_grad = Gradient || (Apic && !bspline_moment);
    const bool remap = extras.remap;
    const bool axisymmetric = options_.kinematics == Kinematics::axisymmetric;
    const long n = range.last(points.size());
    const auto& strides = grid.strides();
    const double alpha = options_.update == VelocityUpdate::flip    ? 1.0
                         : options_.update == VelocityUpdate::blend ? options_.flip_fraction
                                                                    : 0.0;
    // APIC (α = 0) takes the Lagrangian velocity alone: no FLIP increment to gather.
    constexpr bool with_change = !Apic;
    Mat<D>* affine_out = Apic ? points[affine_].data() : nullptr;
    double* heat = Heat ? points[heat_].data() : nullptr;
    const double h = grid.cell();
    const double inertia_scale =
        Kernel::apic_inertia > 0.0 ? 1.0 / (Kernel::apic_inertia * h * h) : 0.0;
    double speed_squared = 0.0;  // the largest |v|²: one square root at the end
    long first_bad = std::numeric_limits<long>::max();
    RangeNodes* nodes = nullptr;
    if (remap) {
      grid.zero_live(grid.momentum);
      buffers_.prepare(grid);
      nodes = &range_nodes(range.begin, n);
    }
#pragma omp parallel reduction(max : speed_squared) reduction(min : first_bad)
    {
      const ThreadTarget target = remap ? thread_target(grid, *nodes) : ThreadTarget{};
#pragma omp for schedule(static) nowait
      for (long p = range.begin; p < n; ++p) {
        const Stencil<D, Kernel> s = stencil(grid, p);
        const Vec<D> v_old = points.velocity[p];
        // Row sums (stencil.hpp): the rows' velocity blocks summed with the factors of the
        // other axes, then contracted with the axis-0 weights: v_L = Σ N_i v_i, Δv = Σ N_i Δv_i,
        // L = Σ v_i ∇N_iᵀ and for APIC either Σ N_i v_i indexᵢᵀ (B-splines: C' = (Σ N_i v_i
        // dx_iᵀ) D⁻¹ with dx_i = (offset + index_i) h) or Σ v_i ∇N_iᵀ (the gradient form).
        RowSums<D, W> rows;
        sum_rows<Apic && bspline_moment, with_grad>(s, strides, grid.velocity, rows);
        double v_lagrangian[D], v_change[D] = {};
        contract_block<D, W>(rows.value, s.w[0], v_lagrangian);
        if constexpr (with_change) {  // the FLIP increment Σ N_i Δv_i
          RowSums<D, W> change;
          sum_rows<false, false>(s, strides, grid.velocity_change, change);
          contract_block<D, W>(change.value, s.w[0], v_change);
        }
        double L[D][D];  // L[e]: column e, with_grad only
        if constexpr (with_grad) {
          contract_block<D, W>(rows.value, s.dw[0], L[0]);
          for (int e = 1; e < D; ++e) contract_block<D, W>(rows.grad[e], s.w[0], L[e]);
        }
        Mat<D> affine;
        if constexpr (Apic && bspline_moment) {
          double moment[D][D], index_w[W];  // moment[e]: column e
          for (int a = 0; a < W; ++a) index_w[a] = a * s.w[0][a];
          contract_block<D, W>(rows.value, index_w, moment[0]);
          for (int e = 1; e < D; ++e) contract_block<D, W>(rows.index[e], s.w[0], moment[e]);
          for (int e = 0; e < D; ++e)
            for (int i = 0; i < D; ++i)
              affine(i, e) = inertia_scale * h * (v_lagrangian[i] * s.offset[e] + moment[e][i]);
        } else if constexpr (Apic) {
          store_gradient(L, affine);
        }
        if constexpr (Heat) {
          // r_in, Σ N |v_i|² and, for the gradient form, the inertia Σ N dx_d² (the B-splines'
          // is the constant apic_inertia h²), node by node.
          double r_in = 0.0, s_new = 0.0;
          Vec<D> inertia = Vec<D>::Constant(Kernel::apic_inertia * h * h);
          const Mat<D> c_old = affine_out[p];
          for_each_node(s, strides, [&](long node, double N, const Vec<D>&, const IVec<D>& index) {
            const Vec<D> dx =
                (Eigen::Map<const Vec<D>>(s.offset) + index.template cast<double>()) * h;
            const Vec<D> v_i = grid.velocity[node], dv_i = grid.velocity_change[node];
            r_in += N * (v_old + c_old * dx - (v_i - dv_i)).squaredNorm();
            s_new += N * v_i.squaredNorm();
            if constexpr (Kernel::apic_inertia == 0.0) inertia += N * dx.cwiseAbs2();
          });
          double affine_energy = 0.0;  // Σ N |C' dx|² = Σ_d D_dd |C' e_d|²
          for (int d = 0; d < D; ++d) affine_energy += inertia[d] * affine.col(d).squaredNorm();
          const double r_out = s_new - Vec<D>(v_lagrangian).squaredNorm() - affine_energy;
          heat[p] = 0.5 * (r_in + r_out);
        }
        // Points move with the Lagrangian grid velocity (IJNME eq 11, second line).
        Vec<D> x, v;
        for (int i = 0; i < D; ++i) {
          x[i] = points.position[p][i] + dt * v_lagrangian[i];
          v[i] = with_change ? alpha * (v_old[i] + v_change[i]) + (1.0 - alpha) * v_lagrangian[i]
                             : v_lagrangian[i];
        }
        // A point on a wall or symmetry face (a membrane's end on a symmetry plane) stays on
        // it: the mirrored ghosts cancel its normal velocity only to round-off. (A copy goes
        // to return_to_face: x itself, its address taken, would live in memory and be written
        // piecewise and read whole, which stalls store forwarding in every step.)
        bool inside = grid.contains(x);
        if (!inside) {
          Vec<D> on_face = x;
          inside = grid.return_to_face(on_face);
          x = on_face;
        }
        if constexpr (Gradient) {
          store_gradient(L, extras.gradient[p]);
          if (axisymmetric) extras.hoop_rate[p] = v_lagrangian[0] / x[0];  // u_r / r
        }
        points.position[p] = x;
        points.velocity[p] = v;
        if constexpr (Apic) affine_out[p] = affine;
        if (!inside || !v.allFinite()) first_bad = std::min(first_bad, p);
        speed_squared = std::max(speed_squared, v.squaredNorm());
        // MUSL's remap (thesis eq 3.24) of this point's new momentum, with the same stencil.
        if (remap)
          scatter_point<false, false, Apic, true>(points, p, s, Vec<D>::Zero(), grid, false,
                                                  affine_out, target);
      }
    }
    if (remap) {
      buffers_.reduce(grid, false, true, false);
      grid.fold(grid.momentum);
    }
    if (first_bad != std::numeric_limits<long>::max()) {
      failure.point = first_bad;
      failure.what =
          points.velocity[first_bad].allFinite() && points.position[first_bad].allFinite()
              ? "the point left the grid domain"
              : "non-finite position or velocity";
    }
    return std::sqrt(speed_squared);
  }

  //! The one scatter loop: mass and momentum (WithMass), forces (WithForce), the APIC affine
  //! momentum term (Affine); MomentumOnly is the MUSL remap (mass already on the grid).
  template <bool WithMass, bool WithForce, bool Affine, bool MomentumOnly = false>
  void scatter(const Particles<D>& points, const Vec<D>& gravity, Grid<D>& grid, PointRange range) {
    constexpr bool with_momentum = WithMass || MomentumOnly;
    const long n = range.last(points.size());
    const bool axisymmetric = options_.kinematics == Kinematics::axisymmetric;
    const Mat<D>* affine = Affine ? points[affine_].data() : nullptr;
    buffers_.prepare(grid);
    RangeNodes& nodes = range_nodes(range.begin, n);
#pragma omp parallel
    {
      const ThreadTarget target = thread_target(grid, nodes);
#pragma omp for schedule(static) nowait
      for (long p = range.begin; p < n; ++p) {
        // The stress, the widest column the scatter reads, sixteen points (eight cache lines in
        // 2D) ahead: the sampled 2D scatter waited on its loads (docs/theory/performance.md).
        if constexpr (WithForce) __builtin_prefetch(points.stress.data() + p + 16);
        scatter_point<WithMass, WithForce, Affine, MomentumOnly>(
            points, p, stencil(grid, p), gravity, grid, axisymmetric, affine, target);
      }
    }
    buffers_.reduce(grid, WithMass, with_momentum, WithForce);
    if constexpr (WithMass) grid.fold(grid.mass);
    if constexpr (with_momentum) grid.fold(grid.momentum);
    if constexpr (WithForce) grid.fold(grid.force);
  }

  //! Where one thread's share of a scatter writes (scatter_buffers.hpp), and whether all of it
  //! goes straight to the grid (every node its points touch lies in its window).
  struct ThreadTarget {
    ScatterTarget<D> target{};
    bool direct = true;
    long stencil_extent = 0;  //!< a stencil's last node less its first (its base)

    //! Whether the stencil `s` writes only nodes of the window: most of a thread's points
    //! when its share borders another's, whose nodes near the border go to its copy.
    bool takes_whole(const Stencil<D, Kernel>& s) const {
      return direct ||
             (s.base >= target.window_first && s.base + stencil_extent <= target.window_last);
    }
  };

  //! What the stencils of one range of points touch (a field's points, or all points), found
  //! by compute_stencils: per thread of a scatter over them with a static schedule, the nodes
  //! its share touches, and the spans of nodes the range may write (Grid::restart_live). The
  //! anchors do not change within a step, so neither do these.
  struct RangeNodes {
    long begin = 0, end = 0;
    int threads = 0;  //!< the team size per_thread was found for; 0: not found yet
    std::vector<std::pair<long, long>> per_thread;
    std::vector<NodeSpan> spans;  //!< empty: every node live
  };

  //! The entry of the points [begin, end), added if new (its node shares are then found by
  //! the first scatter over them). Serial.
  RangeNodes& range_nodes(long begin, long end) {
    const std::size_t threads = omp_get_max_threads();
    for (RangeNodes& nodes : range_nodes_)
      if (nodes.begin == begin && nodes.end == end && nodes.per_thread.size() >= threads)
        return nodes;
    range_nodes_.push_back({begin, end, 0, std::vector<std::pair<long, long>>(threads), {}});
    return range_nodes_.back();
  }

  //! The live spans of the stencils of the points [begin, end): their own, or, for a range
  //! compute_stencils was not told of, those of all points (empty: every node live).
  const std::vector<NodeSpan>& live_spans(long begin, long end) const {
    for (const RangeNodes& nodes : range_nodes_)
      if (nodes.begin == begin && nodes.end == end && !nodes.spans.empty()) return nodes.spans;
    return all_spans_;
  }

  //! This thread's target for a scatter over the points of `nodes` with a static schedule;
  //! called by every thread of a parallel region, after buffers_.prepare().
  ThreadTarget thread_target(Grid<D>& grid, RangeNodes& nodes) {
    const int t = omp_get_thread_num(), threads = omp_get_num_threads();
    // The nodes this thread's points touch (the same static share of the points as the
    // scatter's); a lone thread writes everything into the grid and need not know.
    long lo = std::numeric_limits<long>::max(), hi = -1;
    if (threads > 1) {
      if (nodes.threads == threads) {
        std::tie(lo, hi) = nodes.per_thread[t];
      } else {
#pragma omp for schedule(static) nowait
        for (long p = nodes.begin; p < nodes.end; ++p) extend_node_range(grid, anchors_[p], lo, hi);
        nodes.per_thread[t] = {lo, hi};
      }
      buffers_.touched(t, lo, hi);
#pragma omp barrier
      // Every thread has read nodes.threads before the barrier.
      if (t == 0) nodes.threads = threads;
    }
    ThreadTarget target{buffers_.target(t, grid), true};
    target.direct = target.target.window_first <= lo && hi <= target.target.window_last;
    for (int e = 0; e < D; ++e) target.stencil_extent += (Kernel::width - 1) * grid.strides()[e];
    return target;
  }

  //! One point's share of a scatter, with the stencil `s`, into `target`.
  template <bool WithMass, bool WithForce, bool Affine, bool MomentumOnly>
  [[gnu::always_inline]] void scatter_point(const Particles<D>& points, long p,
                                            const Stencil<D, Kernel>& s, const Vec<D>& gravity,
                                            const Grid<D>& grid, bool axisymmetric,
                                            const Mat<D>* affine,
                                            const ThreadTarget& target) const {
    if (target.takes_whole(s))
      scatter_point_into<WithMass, WithForce, Affine, MomentumOnly>(
          points, p, s, gravity, grid, axisymmetric, affine,
          [&](long) -> const NodeFields<D>& { return target.target.grid; });
    else
      scatter_point_into<WithMass, WithForce, Affine, MomentumOnly>(
          points, p, s, gravity, grid, axisymmetric, affine,
          [&](long node) -> const NodeFields<D>& { return target.target.at(node); });
  }

  //! One point's share of the scatter, into the node fields `fields(node)` gives. Per node i
  //! with weight N_i and x_i − x_p = dx_i:
  //!   mass     N_i m,
  //!   momentum N_i m (v + C dx_i)                  (APIC; C = 0 otherwise),
  //!   force    N_i m (g + a_body) − V σ ∇N_i        (IJNME eq 16; axisymmetric: − N_i V σ_θθ / r).
  //! Row blocks (stencil.hpp): with dx_i = (offset + index_i) h, N_i = φ₀(a)·weight and
  //! ∇N_i = (dφ₀(a)·weight, φ₀(a)·grad_e), a row's momentum block is
  //! weight·M₀ + Σ_{e>0} index_e·weight·M_e and its force block weight·F₀ + Σ_{e>0} grad_e·F_e,
  //! with the per-point blocks (node a, component i)
  //!   M₀ = φ₀(a) (m v + m h C offset + a m h C e₀)_i,   M_e = φ₀(a) m h (C e_e)_i,
  //!   F₀ = φ₀(a) (m (g + a_body) − [i = r] V σ_θθ / r)_i − dφ₀(a) (V σ e₀)_i,   F_e = −φ₀(a) (V σ
  //!   e_e)_i.
  template <bool WithMass, bool WithForce, bool Affine, bool MomentumOnly, class Fields>
  [[gnu::always_inline]] void scatter_point_into(const Particles<D>& points, long p,
                                                 const Stencil<D, Kernel>& s, const Vec<D>& gravity,
                                                 const Grid<D>& grid, bool axisymmetric,
                                                 const Mat<D>* affine, Fields&& fields) const {
    constexpr bool with_momentum = WithMass || MomentumOnly;
    constexpr int W = Kernel::width, K = W * D, J = Affine ? D : 1;
    const double* w = s.w[0];
    const double m = points.mass[p];
    double mass_w[W];
    for (int a = 0; a < W; ++a) mass_w[a] = m * w[a];
    double momentum_blocks[J][K], force_blocks[D][K];  // M_e, F_e
    if constexpr (with_momentum) {
      double q0[D], dq[D][D] = {};  // momentum at the stencil's node 0; dq[e]: per node along e
      for (int i = 0; i < D; ++i) q0[i] = m * points.velocity[p][i];
      if constexpr (Affine) {
        const double h = grid.cell();
        const Mat<D>& C = affine[p];
        for (int i = 0; i < D; ++i) {
          double c_offset = 0.0;
          for (int d = 0; d < D; ++d) c_offset += C(i, d) * s.offset[d];
          q0[i] += m * h * c_offset;
          for (int e = 0; e < D; ++e) dq[e][i] = m * h * C(i, e);
        }
      }
      for (int a = 0; a < W; ++a)
        for (int i = 0; i < D; ++i) {
          if constexpr (Affine)
            momentum_blocks[0][a * D + i] = w[a] * (q0[i] + a * dq[0][i]);
          else
            momentum_blocks[0][a * D + i] = w[a] * q0[i];
          for (int e = 1; e < J; ++e) momentum_blocks[e][a * D + i] = w[a] * dq[e][i];
        }
    }
    if constexpr (WithForce) {
      const Mat3 sigma = to_mat3<D>(points.stress[p]);
      const double V = points.volume[p];
      const Vec<D> acceleration = gravity + points.bodies[points.body[p]].applied_acceleration;
      double external[D];
      for (int i = 0; i < D; ++i) external[i] = m * acceleration[i];
      if (axisymmetric) external[0] -= V * sigma(2, 2) / points.position[p][0];
      for (int a = 0; a < W; ++a)
        for (int i = 0; i < D; ++i) {
          force_blocks[0][a * D + i] = w[a] * external[i] - s.dw[0][a] * (V * sigma(i, 0));
          for (int e = 1; e < D; ++e) force_blocks[e][a * D + i] = -w[a] * (V * sigma(i, e));
        }
    }
    // One row's share, from its first node: mass weight · m φ₀(a), momentum Σ_j mc[j] · mb[j],
    // force Σ_j fc[j] · fb[j].
    const auto add_row = [&]<int JM, int JF>(long first, double weight, const double(&mc)[JM],
                                             const double(&mb)[JM][K], const double(&fc)[JF],
                                             const double(&fb)[JF][K]) {
      const NodeFields<D>& out = fields(first);
      if (&out == &fields(first + W - 1)) {  // the whole row goes to one target
        if constexpr (WithMass)
          for (int a = 0; a < W; ++a) out.mass[first + a] += weight * mass_w[a];
        if constexpr (with_momentum) add_combination(out.momentum[first].data(), mc, mb);
        if constexpr (WithForce) add_combination(out.force[first].data(), fc, fb);
        return;
      }
      double momentum[K] = {}, force[K] = {};
      if constexpr (with_momentum) add_combination(momentum, mc, mb);
      if constexpr (WithForce) add_combination(force, fc, fb);
      for (int a = 0; a < W; ++a) {
        const long node = first + a;
        const NodeFields<D>& target = fields(node);
        if constexpr (WithMass) target.mass[node] += weight * mass_w[a];
        for (int i = 0; i < D; ++i) {
          if constexpr (with_momentum) target.momentum[node][i] += momentum[a * D + i];
          if constexpr (WithForce) target.force[node][i] += force[a * D + i];
        }
      }
    };
    if constexpr (D == 3 && W >= 3) {
      // Plane by plane, as sum_rows. With weight = φ₁(b) φ₂(c), grad_1 = φ₁'(b) φ₂(c) and
      // grad_2 = φ₁(b) φ₂'(c), row (b, c) gets the momentum φ₁(b) A_c + b φ₁(b) B_c (APIC)
      // and the force φ₁(b) G_c + φ₁'(b) H_c, with the plane's blocks
      //   A_c = φ₂(c) M₀ + c φ₂(c) M₂,   B_c = φ₂(c) M₁,
      //   G_c = φ₂(c) F₀ + φ₂'(c) F₂,    H_c = φ₂(c) F₁:
      // two blocks per row for each, where the row-by-row form combines three.
      const auto& strides = grid.strides();
      for (int c = 0; c < W; ++c) {
        const double phi2 = s.w[2][c];
        double plane_momentum[2][K], plane_force[2][K];  // A_c, B_c; G_c, H_c
        if constexpr (with_momentum && Affine) {
          combine_blocks(plane_momentum[0], {phi2, c * phi2},
                         {momentum_blocks[0], momentum_blocks[2]});
          combine_blocks(plane_momentum[1], {phi2}, {momentum_blocks[1]});
        }
        if constexpr (WithForce) {
          combine_blocks(plane_force[0], {phi2, s.dw[2][c]}, {force_blocks[0], force_blocks[2]});
          combine_blocks(plane_force[1], {phi2}, {force_blocks[1]});
        }
        for (int b = 0; b < W; ++b) {
          const long first = s.base + b * strides[1] + c * strides[2];
          const double weight = s.w[1][b] * phi2;
          const double force_factors[2] = {s.w[1][b], s.dw[1][b]};
          if constexpr (Affine) {
            const double momentum_factors[2] = {s.w[1][b], b * s.w[1][b]};
            add_row(first, weight, momentum_factors, plane_momentum, force_factors, plane_force);
          } else {
            const double momentum_factors[1] = {weight};
            add_row(first, weight, momentum_factors, momentum_blocks, force_factors, plane_force);
          }
        }
      }
    } else {
      for_each_row(s, grid.strides(), [&](const StencilRow<D>& row) {
        double momentum_factors[J], force_factors[D];
        momentum_factors[0] = force_factors[0] = row.weight;
        for (int e = 1; e < J; ++e) momentum_factors[e] = row.index[e] * row.weight;
        for (int e = 1; e < D; ++e) force_factors[e] = row.grad[e];
        add_row(row.first, row.weight, momentum_factors, momentum_blocks, force_factors,
                force_blocks);
      });
    }
  }

  //! L from its columns (L[e]: column e).
  static void store_gradient(const double (&L)[D][D], Mat<D>& out) {
    for (int e = 0; e < D; ++e)
      for (int i = 0; i < D; ++i) out(i, e) = L[e][i];
  }

  //! Widen [lo, hi] to the flat indices of the nodes of an anchor's stencil.
  void extend_node_range(const Grid<D>& grid, const StencilAnchor<D>& anchor, long& lo,
                         long& hi) const {
    IVec<D> first;
    for (int d = 0; d < D; ++d) first[d] = anchor.first[d];
    const long base = grid.flatten(first);
    long last = base;
    for (int d = 0; d < D; ++d) last += (Kernel::width - 1) * grid.strides()[d];
    lo = std::min(lo, base);
    hi = std::max(hi, last);
  }

  //! The nodes along axis 0 that the stencils of consecutive points reach, kept per stencil
  //! first row: `first_rows[r]` spans what the stencils whose first row is r reach in each of
  //! their rows (stencil_spans() spreads them over all rows). Consecutive points mostly share
  //! their first row, so a run of them is gathered here and written once, when it ends.
  struct RowReach {
    int run[D] = {};     //!< the run's first node on each axis (axis 0: its smallest)
    bool open = false;   //!< a run is being gathered
    bool inside = true;  //!< every stencil so far lies within the grid's storage
    NodeSpan span;       //!< the run's nodes along axis 0 (grid indices)
    void add(const Grid<D>& grid, const StencilAnchor<D>& anchor,
             std::vector<NodeSpan>& first_rows) {
      bool same = open;
      for (int d = 1; d < D; ++d) same = same && anchor.first[d] == run[d];
      if (!same) {
        flush(grid, first_rows);
        for (int d = 1; d < D; ++d) run[d] = anchor.first[d];
        open = true;
      }
      span.add(anchor.first[0], anchor.first[0] + Kernel::width - 1);
    }
    //! End the run: its first row takes its span, or, when a stencil of it does not lie
    //! within the storage, `inside` turns false.
    void flush(const Grid<D>& grid, std::vector<NodeSpan>& first_rows) {
      if (!open) return;
      open = false;
      run[0] = span.first;
      for (int d = 0; d < D; ++d) {
        const int end = (d == 0 ? span.last : run[d] + Kernel::width - 1) - grid.first()[d];
        if (run[d] < grid.first()[d] || end >= grid.nodes()[d]) inside = false;
      }
      if (inside)
        first_rows[grid.row_of(run)].add(span.first - grid.first()[0], span.last - grid.first()[0]);
      span = NodeSpan{};
    }
  };

  //! The spans of every row from those of the stencils' first rows: row (j[, k]) holds the
  //! stencils whose first row is (j − b[, k − c]) for b[, c] = 0..W−1, one axis at a time.
  static void stencil_spans(const Grid<D>& grid, std::vector<NodeSpan>& spans) {
    constexpr int W = Kernel::width;
    const long rows = grid.row_count();
    for (int d = 1; d < D; ++d) {
      const long step = d == 1 ? 1 : grid.nodes()[1], n = grid.nodes()[d];
      for (long r = rows - 1; r >= 0; --r) {  // downwards, so each row reads first rows only
        const long j = (r / step) % n;
        for (int b = 1; b < W && b <= j; ++b)
          spans[r].add(spans[r - b * step].first, spans[r - b * step].last);
      }
    }
  }

  //! This step's stencil of point p, rebuilt from its anchor (docs/theory/performance.md).
  Stencil<D, Kernel> stencil(const Grid<D>& grid, long p) const {
    Stencil<D, Kernel> s;
    expand_stencil(kernel_, grid, anchors_[p], s);
    return s;
  }

  TransferOptions options_;
  Column<Mat<D>> affine_;  //!< APIC only: C_p
  Column<double> heat_;    //!< APIC with a thermal model: dissipated energy per mass
  Kernel kernel_;
  std::vector<StencilAnchor<D>> anchors_;  //!< per point, at the step's start positions
  std::vector<RangeNodes> range_nodes_;    //!< this step's, per point range scattered
  //! The rows the stencils of all points reach (Grid::restart_live); per thread and range,
  //! the spans of the stencils' first rows (compute_stencils' work).
  std::vector<NodeSpan> all_spans_;
  std::vector<std::vector<NodeSpan>> thread_spans_;
  ScatterBuffers<D> buffers_;
};

}  // namespace pellicle
