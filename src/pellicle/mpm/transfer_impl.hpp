#pragma once
//! Kernel-templated implementation of the transfers. Included only by the per-kernel
//! instantiation files (transfer_*.cpp), so the heavy inlining is compiled once per kernel.

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

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
    double energy = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : energy)
    for (long p = 0; p < n; ++p) {
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
      energy += 0.5 * points.mass[p] * h * h * e;
    }
    return energy;
  }

  std::size_t stencil_bytes() const override {
    return sizeof(StencilAnchor<D>);
  }

  void compute_stencils(const Particles<D>& points, const Grid<D>& grid) override {
    const long n = points.size();
    anchors_.resize(n);
    anchored_points_ = n;
#pragma omp parallel
    {
      // With threads, each one's node range for the scatters over all points (thread_target),
      // from the same static share of the points, so the scatters need not read the anchors
      // an extra time to find it.
      const bool ranges = omp_get_num_threads() > 1;
      long lo = std::numeric_limits<long>::max(), hi = -1;
#pragma omp for schedule(static) nowait
      for (long p = 0; p < n; ++p) {
        anchors_[p] = stencil_anchor(kernel_, grid, points.position[p]);
        if (ranges) extend_node_range(grid, anchors_[p], lo, hi);
      }
#pragma omp single
      anchored_ranges_.assign(omp_get_num_threads(), {0, -1});
      anchored_ranges_[omp_get_thread_num()] = {lo, hi};
    }
  }

  void to_grid(const Particles<D>& points, const Vec<D>& gravity, Grid<D>& grid, bool forces,
               PointRange range) override {
    zero(grid.mass);
    zero(grid.momentum);
    if (forces) zero(grid.force);
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
    zero(grid.force);
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
    zero(grid.momentum);
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
    for (long p = begin; p < end; ++p) {
      const Stencil<D, Kernel> s = stencil(grid, p);
      double L[D][D] = {}, v_radial = 0.0;
      for_each_row(s, strides, [&](const StencilRow<D>& row) {
        double sum_w[D] = {}, sum_dw[D] = {};
        for (int a = 0; a < Kernel::width; ++a) {
          const double* v_node = grid.velocity[row.first + a].data();
          for (int i = 0; i < D; ++i) {
            sum_w[i] += s.w[0][a] * v_node[i];
            sum_dw[i] += s.dw[0][a] * v_node[i];
          }
        }
        add_row_gradient(row, sum_w, sum_dw, L, v_radial);
      });
      store_gradient(L, gradient[p - begin]);
      double volumetric = 0.0;
      for (int i = 0; i < D; ++i) volumetric += L[i][i];
      if (axisymmetric) {
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
    const bool remap = extras.remap;
    const bool axisymmetric = options_.kinematics == Kinematics::axisymmetric;
    const long n = range.last(points.size());
    const auto& strides = grid.strides();
    const double alpha = options_.update == VelocityUpdate::flip    ? 1.0
                         : options_.update == VelocityUpdate::blend ? options_.flip_fraction
                                                                    : 0.0;
    Mat<D>* affine_out = Apic ? points[affine_].data() : nullptr;
    double* heat = Heat ? points[heat_].data() : nullptr;
    const double h = grid.cell();
    const double inertia_scale =
        Kernel::apic_inertia > 0.0 ? 1.0 / (Kernel::apic_inertia * h * h) : 0.0;
    double speed_squared = 0.0;  // the largest |v|²: one square root at the end
    long first_bad = std::numeric_limits<long>::max();
    if (remap) {
      zero(grid.momentum);
      buffers_.prepare(grid);
    }
#pragma omp parallel reduction(max : speed_squared) reduction(min : first_bad)
    {
      const ThreadTarget target = remap ? thread_target(grid, range.begin, n) : ThreadTarget{};
#pragma omp for schedule(static) nowait
      for (long p = range.begin; p < n; ++p) {
        const Stencil<D, Kernel> s = stencil(grid, p);
        // Row by row (StencilRow): v_L = Σ N_i v_i, Δv = Σ N_i Δv_i and for APIC either
        // Σ N_i v_i indexᵢᵀ (B-splines: C' = (Σ N_i v_i dx_iᵀ) D⁻¹ with dx_i = (offset + index_i)
        // h) or Σ v_i ∇N_iᵀ (the gradient form).
        double v_lagrangian[D] = {}, v_change[D] = {}, moment[D][D] = {};  // moment[d]: column d
        // Heat only: r_in, Σ N |v_i|² and, for the gradient form, the inertia Σ N dx_d² (the
        // B-splines' is the constant apic_inertia h²).
        double r_in = 0.0, s_new = 0.0;
        double L[D][D] = {}, v_radial = 0.0;  // Gradient only
        Vec<D> inertia = Vec<D>::Constant(Kernel::apic_inertia * h * h);
        const Vec<D> v_old = points.velocity[p];
        Mat<D> c_old;
        if constexpr (Heat) c_old = affine_out[p];
        for_each_row(s, strides, [&](const StencilRow<D>& row) {
          double sum_w[D] = {}, sum_change[D] = {}, sum_moment[D] = {}, sum_dw[D] = {};
          for (int a = 0; a < Kernel::width; ++a) {
            const long node = row.first + a;
            const double* v_node = grid.velocity[node].data();
            const double* dv_node = grid.velocity_change[node].data();
            const double w = s.w[0][a];
            const double moment_weight = Kernel::apic_inertia > 0.0 ? a * w : s.dw[0][a];
            for (int i = 0; i < D; ++i) {
              sum_w[i] += w * v_node[i];
              sum_change[i] += w * dv_node[i];
              if constexpr (Apic) sum_moment[i] += moment_weight * v_node[i];
              if constexpr (Gradient) sum_dw[i] += s.dw[0][a] * v_node[i];
            }
            if constexpr (Heat) {
              const double N = w * row.weight;
              Vec<D> dx;
              for (int d = 0; d < D; ++d) dx[d] = (s.offset[d] + (d == 0 ? a : row.index[d])) * h;
              const Vec<D> v_i = grid.velocity[node], dv_i = grid.velocity_change[node];
              r_in += N * (v_old + c_old * dx - (v_i - dv_i)).squaredNorm();
              s_new += N * v_i.squaredNorm();
              if constexpr (Kernel::apic_inertia == 0.0) inertia += N * dx.cwiseAbs2();
            }
          }
          for (int i = 0; i < D; ++i) {
            v_lagrangian[i] += row.weight * sum_w[i];
            v_change[i] += row.weight * sum_change[i];
            if constexpr (Apic) {
              moment[0][i] += row.weight * sum_moment[i];
              for (int e = 1; e < D; ++e)
                moment[e][i] +=
                    (Kernel::apic_inertia > 0.0 ? row.index[e] * row.weight : row.grad[e]) *
                    sum_w[i];
            }
          }
          if constexpr (Gradient) add_row_gradient(row, sum_w, sum_dw, L, v_radial);
        });
        Mat<D> affine;
        if constexpr (Apic) {
          for (int e = 0; e < D; ++e)
            for (int i = 0; i < D; ++i)
              affine(i, e) =
                  Kernel::apic_inertia > 0.0
                      ? inertia_scale * h * (v_lagrangian[i] * s.offset[e] + moment[e][i])
                      : moment[e][i];
        }
        if constexpr (Heat) {
          double affine_energy = 0.0;  // Σ N |C' dx|² = Σ_d D_dd |C' e_d|²
          for (int d = 0; d < D; ++d) affine_energy += inertia[d] * affine.col(d).squaredNorm();
          const double r_out = s_new - Vec<D>(v_lagrangian).squaredNorm() - affine_energy;
          heat[p] = 0.5 * (r_in + r_out);
        }
        // Points move with the Lagrangian grid velocity (IJNME eq 11, second line).
        Vec<D> x, v;
        for (int i = 0; i < D; ++i) {
          x[i] = points.position[p][i] + dt * v_lagrangian[i];
          v[i] = alpha * (v_old[i] + v_change[i]) + (1.0 - alpha) * v_lagrangian[i];
        }
        // A point on a wall or symmetry face (a membrane's end on a symmetry plane) stays on
        // it: the mirrored ghosts cancel its normal velocity only to round-off.
        const bool inside = grid.contains(x) || grid.return_to_face(x);
        if constexpr (Gradient) {
          store_gradient(L, extras.gradient[p]);
          if (axisymmetric) extras.hoop_rate[p] = v_radial / x[0];
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

  template <class T>
  static void zero(std::vector<T>& field) {
    const long n = static_cast<long>(field.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
      if constexpr (std::is_same_v<T, double>)
        field[i] = 0.0;
      else
        field[i].setZero();
    }
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
#pragma omp parallel
    {
      const ThreadTarget target = thread_target(grid, range.begin, n);
#pragma omp for schedule(static) nowait
      for (long p = range.begin; p < n; ++p)
        scatter_point<WithMass, WithForce, Affine, MomentumOnly>(
            points, p, stencil(grid, p), gravity, grid, axisymmetric, affine, target);
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
  };

  //! This thread's target for a scatter over points [begin, end) with a static schedule; called
  //! by every thread of a parallel region, after buffers_.prepare().
  ThreadTarget thread_target(Grid<D>& grid, long begin, long end) {
    const int t = omp_get_thread_num();
    // The nodes this thread's points touch (the same static share of the points as the
    // scatter's); a lone thread writes everything into the grid and need not know.
    long lo = std::numeric_limits<long>::max(), hi = -1;
    if (omp_get_num_threads() > 1) {
      if (begin == 0 && end == anchored_points_ &&
          static_cast<int>(anchored_ranges_.size()) == omp_get_num_threads()) {
        std::tie(lo, hi) = anchored_ranges_[t];
      } else {
#pragma omp for schedule(static) nowait
        for (long p = begin; p < end; ++p) extend_node_range(grid, anchors_[p], lo, hi);
      }
      buffers_.touched(t, lo, hi);
#pragma omp barrier
    }
    ThreadTarget target{buffers_.target(t, grid), true};
    target.direct = target.target.window_first <= lo && hi <= target.target.window_last;
    return target;
  }

  //! One point's share of a scatter, with the stencil `s`, into `target`.
  template <bool WithMass, bool WithForce, bool Affine, bool MomentumOnly>
  void scatter_point(const Particles<D>& points, long p, const Stencil<D, Kernel>& s,
                     const Vec<D>& gravity, const Grid<D>& grid, bool axisymmetric,
                     const Mat<D>* affine, const ThreadTarget& target) const {
    if (target.direct)
      scatter_point_into<WithMass, WithForce, Affine, MomentumOnly>(
          points, p, s, gravity, grid, axisymmetric, affine,
          [&](long) -> const NodeFields<D>& { return target.target.grid; });
    else
      scatter_point_into<WithMass, WithForce, Affine, MomentumOnly>(
          points, p, s, gravity, grid, axisymmetric, affine,
          [&](long node) -> const NodeFields<D>& { return target.target.at(node); });
  }

  //! One point's share of the scatter, into the node fields `fields(node)` gives, row by row
  //! (StencilRow): per node i with weight N_i and x_i − x_p = dx_i,
  //!   mass     N_i m,
  //!   momentum N_i m (v + C dx_i)                  (APIC; C = 0 otherwise),
  //!   force    N_i m (g + a_body) − V σ ∇N_i        (IJNME eq 16; axisymmetric: − N_i V σ_θθ / r).
  //! With dx_i = (offset + index_i) h the momentum is N_i (q₀ + Σ_d index_i,d m h C e_d), and with
  //! the gradient split of a row, V σ ∇N_i = dφ₀(a) (weight V σ e₀) + φ₀(a) Σ_{e>0} grad_e V σ e_e:
  //! each row folds its factors into a few vectors and its nodes take one multiply-add per
  //! component and field.
  template <bool WithMass, bool WithForce, bool Affine, bool MomentumOnly, class Fields>
  void scatter_point_into(const Particles<D>& points, long p, const Stencil<D, Kernel>& s,
                          const Vec<D>& gravity, const Grid<D>& grid, bool axisymmetric,
                          const Mat<D>* affine, Fields&& fields) const {
    constexpr bool with_momentum = WithMass || MomentumOnly;
    constexpr int W = Kernel::width;
    const double h = grid.cell();
    const double m = points.mass[p];
    double q0[D],
        dq[D][D] = {};  // momentum per unit weight at stencil node 0; dq[e]: per node along e
    for (int i = 0; i < D; ++i) q0[i] = m * points.velocity[p][i];
    if constexpr (Affine) {
      const Mat<D>& C = affine[p];
      for (int i = 0; i < D; ++i) {
        double c_offset = 0.0;
        for (int d = 0; d < D; ++d) c_offset += C(i, d) * s.offset[d];
        q0[i] += m * h * c_offset;
        for (int e = 0; e < D; ++e) dq[e][i] = m * h * C(i, e);
      }
    }
    double stress_volume[D][D] = {};  // column e of V_p σ_p (in-plane part)
    double external[D] = {}, hoop_over_r = 0.0;
    if constexpr (WithForce) {
      const Mat3 sigma = to_mat3<D>(points.stress[p]);
      const double V = points.volume[p];
      for (int e = 0; e < D; ++e)
        for (int i = 0; i < D; ++i) stress_volume[e][i] = V * sigma(i, e);
      if (axisymmetric) hoop_over_r = V * sigma(2, 2) / points.position[p][0];
      const Vec<D> acceleration = gravity + points.bodies[points.body[p]].applied_acceleration;
      for (int i = 0; i < D; ++i) external[i] = m * acceleration[i];
    }
    for_each_row(s, grid.strides(), [&](const StencilRow<D>& row) {
      const double row_mass = row.weight * m;
      double momentum[D], step[D], force_w[D], force_dw[D];
      for (int i = 0; i < D; ++i) {
        double q = q0[i];
        if constexpr (Affine)
          for (int e = 1; e < D; ++e) q += row.index[e] * dq[e][i];
        momentum[i] = row.weight * q;
        step[i] = row.weight * dq[0][i];
        force_dw[i] = row.weight * stress_volume[0][i];
        double f = row.weight * external[i];
        for (int e = 1; e < D; ++e) f -= row.grad[e] * stress_volume[e][i];
        force_w[i] = f;
      }
      if (axisymmetric) force_w[0] -= row.weight * hoop_over_r;
      for (int a = 0; a < W; ++a) {
        const long node = row.first + a;
        const NodeFields<D>& out = fields(node);
        const double w = s.w[0][a], dw = s.dw[0][a];
        if constexpr (WithMass) out.mass[node] += w * row_mass;
        if constexpr (with_momentum) {
          double* target = out.momentum[node].data();
          for (int i = 0; i < D; ++i) target[i] += w * momentum[i];
          if constexpr (Affine)
            for (int i = 0; i < D; ++i) momentum[i] += step[i];
        }
        if constexpr (WithForce) {
          double* target = out.force[node].data();
          for (int i = 0; i < D; ++i) target[i] += w * force_w[i] - dw * force_dw[i];
        }
      }
    });
  }

  //! One row's share (StencilRow) of L = Σ_i v_i ∇N_iᵀ and of Σ_i N_i v_i,r, from the row's
  //! sums Σ_a φ₀(a) v_i (sum_w) and Σ_a dφ₀(a) v_i (sum_dw): column 0 of L from sum_dw, the
  //! others from sum_w.
  static void add_row_gradient(const StencilRow<D>& row, const double* sum_w, const double* sum_dw,
                               double (&L)[D][D], double& v_radial) {
    for (int i = 0; i < D; ++i) {
      L[i][0] += row.weight * sum_dw[i];
      for (int e = 1; e < D; ++e) L[i][e] += row.grad[e] * sum_w[i];
    }
    v_radial += row.weight * sum_w[0];
  }
  static void store_gradient(const double (&L)[D][D], Mat<D>& out) {
    for (int e = 0; e < D; ++e)
      for (int i = 0; i < D; ++i) out(i, e) = L[i][e];
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
  long anchored_points_ = 0;               //!< the number of points anchors_ was made for
  //! Per thread of compute_stencils, the nodes its static share of all points touches
  //! (only with more than one thread).
  std::vector<std::pair<long, long>> anchored_ranges_;
  ScatterBuffers<D> buffers_;
};

}  // namespace pellicle
