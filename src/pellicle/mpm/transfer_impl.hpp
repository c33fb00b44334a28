#pragma once
//! Kernel-templated implementation of the transfers. Included only by the per-kernel
//! instantiation files (transfer_*.cpp), so the heavy inlining is compiled once per kernel.

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "pellicle/mpm/scatter_buffers.hpp"
#include "pellicle/mpm/shape/kernels.hpp"
#include "pellicle/mpm/shape/stencil.hpp"
#include "pellicle/mpm/transfer.hpp"

namespace pellicle {

//! The small vector products of the node loops written element by element in 3D: Eigen's
//! packet code for 3-vectors spills to the stack inside these loops and runs several times
//! slower (a 2D vector is one SSE2 packet, and there Eigen's code is the fast one). Each keeps
//! the order of operations of the Eigen expression it replaced, so results are bitwise those
//! of before (docs/theory/performance.md).
namespace node_algebra {
//! y += a x
template <int D>
inline void add_scaled(Vec<D>& y, double a, const Vec<D>& x) {
  if constexpr (D == 2)
    y += a * x;  // one SSE2 packet: Eigen's code is the fast one
  else
    for (int i = 0; i < D; ++i) y[i] += a * x[i];
}
//! M += u vᵀ
template <int D>
inline void add_outer(Mat<D>& M, const Vec<D>& u, const Vec<D>& v) {
  if constexpr (D == 2)
    M += u * v.transpose();
  else
    for (int j = 0; j < D; ++j)
      for (int i = 0; i < D; ++i) M(i, j) += u[i] * v[j];
}
//! momentum += c (C dx): the APIC term of the scatter. In 3D term by term with Eigen's
//! grouping of a matrix-vector product (the scalar folded into the matrix; rows 0 and 1 as one
//! packet, ((t0 + t1) + t2), the third row as its tail, t0 + (t1 + t2)).
template <int D>
inline void add_affine(Vec<D>& momentum, double c, const Mat<D>& C, const Vec<D>& dx) {
  if constexpr (D == 2) {
    momentum += c * (C * dx);
  } else {
    for (int i = 0; i < 3; ++i) {
      const double t0 = (c * C(i, 0)) * dx[0], t1 = (c * C(i, 1)) * dx[1],
                   t2 = (c * C(i, 2)) * dx[2];
      momentum[i] += i < 2 ? (t0 + t1) + t2 : t0 + (t1 + t2);
    }
  }
}
//! force += N external − S ∇N (IJNME eq 16), S = V σ; the product grouped as in add_affine.
template <int D>
inline void add_force(Vec<D>& force, double N, const Vec<D>& external, const Mat<D>& S,
                      const Vec<D>& grad) {
  if constexpr (D == 2) {
    force += N * external - S * grad;
  } else {
    for (int i = 0; i < 3; ++i) {
      const double t0 = S(i, 0) * grad[0], t1 = S(i, 1) * grad[1], t2 = S(i, 2) * grad[2];
      force[i] += N * external[i] - (i < 2 ? (t0 + t1) + t2 : t0 + (t1 + t2));
    }
  }
}
}  // namespace node_algebra

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
#pragma omp parallel for schedule(static)
    for (long p = 0; p < n; ++p) anchors_[p] = stencil_anchor(kernel_, grid, points.position[p]);
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

  double to_points(const Grid<D>& grid, double dt, Particles<D>& points, PointFailure& failure,
                   PointRange range) override {
    return heat_.valid() ? move_points<true>(grid, dt, points, failure, range)
                         : move_points<false>(grid, dt, points, failure, range);
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
      Mat<D> L = Mat<D>::Zero();
      double v_radial = 0.0;
      for_each_node(stencil(grid, p), strides,
                    [&](long node, double N, const Vec<D>& grad, const IVec<D>&) {
                      node_algebra::add_outer<D>(L, grid.velocity[node], grad);
                      if (axisymmetric) v_radial += N * grid.velocity[node][0];
                    });
      gradient[p - begin] = L;
      double volumetric = L.trace();
      if (axisymmetric) {
        hoop_rate[p - begin] = v_radial / points.position[p][0];
        volumetric += hoop_rate[p - begin];
      }
      const double rho = points.density[p] / (1.0 + dt * volumetric);
      points.density[p] = rho;
      points.volume[p] = points.mass[p] / rho;
      if (!(rho > 0.0 && rho < std::numeric_limits<double>::infinity()) && first_bad < 0)
        first_bad = p;
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
  template <bool Heat>
  double move_points(const Grid<D>& grid, double dt, Particles<D>& points, PointFailure& failure,
                     PointRange range) {
    const long n = range.last(points.size());
    const auto& strides = grid.strides();
    const double alpha = options_.update == VelocityUpdate::flip    ? 1.0
                         : options_.update == VelocityUpdate::blend ? options_.flip_fraction
                                                                    : 0.0;
    const bool apic_update = apic();
    Mat<D>* affine_out = apic_update ? points[affine_].data() : nullptr;
    double* heat = Heat ? points[heat_].data() : nullptr;
    const double h = grid.cell();
    const double inertia_scale =
        Kernel::apic_inertia > 0.0 ? 1.0 / (Kernel::apic_inertia * h * h) : 0.0;
    double speed_squared = 0.0;  // the largest |v|²: one square root at the end
    long first_bad = std::numeric_limits<long>::max();
#pragma omp parallel for schedule(static) reduction(max : speed_squared) reduction(min : first_bad)
    for (long p = range.begin; p < n; ++p) {
      const Stencil<D, Kernel> s = stencil(grid, p);
      Vec<D> v_lagrangian = Vec<D>::Zero();
      Vec<D> v_change = Vec<D>::Zero();
      Mat<D> affine = Mat<D>::Zero();
      // Heat only: r_in, Σ N |v_i|² and, for the gradient form, the inertia Σ N dx_d² (the
      // B-splines' is the constant apic_inertia h²).
      double r_in = 0.0, s_new = 0.0;
      Vec<D> inertia = Vec<D>::Constant(Kernel::apic_inertia * h * h);
      const Vec<D> v_old = points.velocity[p];
      Mat<D> c_old;
      if constexpr (Heat) c_old = affine_out[p];
      for_each_node(s, strides, [&](long node, double N, const Vec<D>& grad, const IVec<D>& a) {
        const Vec<D>& v_node = grid.velocity[node];
        const Vec<D>& dv_node = grid.velocity_change[node];
        node_algebra::add_scaled<D>(v_lagrangian, N, v_node);
        node_algebra::add_scaled<D>(v_change, N, dv_node);
        if (apic_update) {
          Vec<D> dx;
          for (int d = 0; d < D; ++d) dx[d] = (s.offset[d] + a[d]) * h;
          if constexpr (Kernel::apic_inertia > 0.0) {
            Vec<D> scaled;  // (N / (D_dd h²)) v_i
            for (int d = 0; d < D; ++d) scaled[d] = (N * inertia_scale) * v_node[d];
            node_algebra::add_outer<D>(affine, scaled, dx);
          } else {
            node_algebra::add_outer<D>(affine, v_node, grad);
          }
          if constexpr (Heat) {
            r_in += N * (v_old + c_old * dx - (v_node - dv_node)).squaredNorm();
            s_new += N * v_node.squaredNorm();
            if constexpr (Kernel::apic_inertia == 0.0) inertia += N * dx.cwiseAbs2();
          }
        }
      });
      if constexpr (Heat) {
        double affine_energy = 0.0;  // Σ N |C' dx|² = Σ_d D_dd |C' e_d|²
        for (int d = 0; d < D; ++d) affine_energy += inertia[d] * affine.col(d).squaredNorm();
        const double r_out = s_new - v_lagrangian.squaredNorm() - affine_energy;
        heat[p] = 0.5 * (r_in + r_out);
      }
      // Points move with the Lagrangian grid velocity (IJNME eq 11, second line).
      Vec<D> x = points.position[p] + dt * v_lagrangian;
      Vec<D> v = alpha * (v_old + v_change) + (1.0 - alpha) * v_lagrangian;
      // A point on a wall or symmetry face (a membrane's end on a symmetry plane) stays on
      // it: the mirrored ghosts cancel its normal velocity only to round-off.
      const bool inside = grid.contains(x) || grid.return_to_face(x);
      points.position[p] = x;
      points.velocity[p] = v;
      if (apic_update) affine_out[p] = affine;
      if (!inside || !v.allFinite()) first_bad = std::min(first_bad, p);
      speed_squared = std::max(speed_squared, v.squaredNorm());
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
    const auto& strides = grid.strides();
    const bool axisymmetric = options_.kinematics == Kinematics::axisymmetric;
    const Mat<D>* affine = Affine ? points[affine_].data() : nullptr;
    buffers_.prepare(grid);
#pragma omp parallel
    {
      const int t = omp_get_thread_num();
      // The nodes this thread's points touch (the same static share of the points as below);
      // a lone thread writes everything into the grid and need not know.
      long lo = std::numeric_limits<long>::max(), hi = -1;
      if (omp_get_num_threads() > 1) {
#pragma omp for schedule(static) nowait
        for (long p = range.begin; p < n; ++p) {
          IVec<D> first;
          for (int d = 0; d < D; ++d) first[d] = anchors_[p].first[d];
          const long base = grid.flatten(first);
          lo = std::min(lo, base);
          hi = std::max(hi, base + last_node_offset(strides));
        }
        buffers_.touched(t, lo, hi);
#pragma omp barrier
      }
      const ScatterTarget<D> target = buffers_.target(t, grid);
      // Every node of a thread whose whole range is its window goes to the grid: no test.
      const bool direct = target.window_first <= lo && hi <= target.window_last;
#pragma omp for schedule(static) nowait
      for (long p = range.begin; p < n; ++p) {
        if (direct)
          scatter_point<WithMass, WithForce, Affine, MomentumOnly>(
              points, p, gravity, grid, axisymmetric, affine,
              [&](long) -> const NodeFields<D>& { return target.grid; });
        else
          scatter_point<WithMass, WithForce, Affine, MomentumOnly>(
              points, p, gravity, grid, axisymmetric, affine,
              [&](long node) -> const NodeFields<D>& { return target.at(node); });
      }
    }
    buffers_.reduce(grid, WithMass, with_momentum, WithForce);
    if constexpr (WithMass) grid.fold(grid.mass);
    if constexpr (with_momentum) grid.fold(grid.momentum);
    if constexpr (WithForce) grid.fold(grid.force);
  }

  //! One point's share of the scatter, into the node fields `fields(node)` gives.
  template <bool WithMass, bool WithForce, bool Affine, bool MomentumOnly, class Fields>
  void scatter_point(const Particles<D>& points, long p, const Vec<D>& gravity, const Grid<D>& grid,
                     bool axisymmetric, const Mat<D>* affine, Fields&& fields) const {
    constexpr bool with_momentum = WithMass || MomentumOnly;
    const double h = grid.cell();
    const Stencil<D, Kernel> s = stencil(grid, p);
    const double m = points.mass[p];
    const Vec<D> mv = m * points.velocity[p];
    Mat<D> stress_volume;  // V_p σ_p, in-plane part
    double hoop_over_r = 0.0;
    Vec<D> external = Vec<D>::Zero();
    if constexpr (WithForce) {
      const Mat3 sigma = to_mat3<D>(points.stress[p]);
      stress_volume = points.volume[p] * sigma.template topLeftCorner<D, D>();
      if (axisymmetric) hoop_over_r = points.volume[p] * sigma(2, 2) / points.position[p][0];
      external = m * (gravity + points.bodies[points.body[p]].applied_acceleration);
    }
    Mat<D> C;  // a copy: the compiler need not reload it after every store to the grid
    if constexpr (Affine) C = affine[p];
    for_each_node(s, grid.strides(),
                  [&](long node, double N, const Vec<D>& grad, const IVec<D>& a) {
                    const NodeFields<D>& out = fields(node);
                    if constexpr (WithMass) out.mass[node] += N * m;
                    if constexpr (with_momentum) {
                      Vec<D> momentum = out.momentum[node];
                      node_algebra::add_scaled<D>(momentum, N, mv);
                      if constexpr (Affine) {
                        Vec<D> dx;
                        for (int d = 0; d < D; ++d) dx[d] = (s.offset[d] + a[d]) * h;
                        node_algebra::add_affine<D>(momentum, N * m, C, dx);
                      }
                      out.momentum[node] = momentum;
                    }
                    if constexpr (WithForce) {
                      Vec<D> force = out.force[node];
                      node_algebra::add_force<D>(force, N, external, stress_volume, grad);
                      if (axisymmetric) force[0] -= N * hoop_over_r;
                      out.force[node] = force;
                    }
                  });
  }

  static long last_node_offset(const std::array<long, D>& strides) {
    long offset = 0;
    for (int d = 0; d < D; ++d) offset += (Kernel::width - 1) * strides[d];
    return offset;
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
  ScatterBuffers<D> buffers_;
};

}  // namespace pellicle
