#pragma once
//! The per-point stencil of a kernel: the first node it touches, and per axis the 1D weights
//! and weight derivatives. Fixed once per step (DESIGN: stage `stencils`) as an anchor per
//! point, from which every transfer of that step rebuilds it. The D-dimensional weight of
//! node (a, b[, c]) of the stencil is w[0][a]·w[1][b]·w[2][c]; its gradient is the product
//! rule over the axes.

#include <array>
#include <cstring>
#include <type_traits>
#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/mpm/grid.hpp"

namespace pellicle {

template <int D, class Kernel>
struct Stencil {
  static constexpr int width = Kernel::width;
  static constexpr int size = D == 2 ? width * width : width * width * width;
  long base;            //!< flat index of node (0, 0[, 0]) of the stencil
  double offset[D];     //!< (x_node(0) − x_p)/h per axis, for APIC's x_i − x_p
  double w[D][width];   //!< 1D weights φ
  double dw[D][width];  //!< 1D derivatives dφ/dx (already divided by h)
};

//! What a stage needs to rebuild a point's stencil quickly: its coordinates in cell units and
//! its first node per axis. Kept per point between the stages of a step (the stencil itself
//! is 3–7 times larger; storing it and reading it back costs more than rebuilding it).
template <int D>
struct StencilAnchor {
  double xi[D];  //!< ξ = (x − origin)/h
  int first[D];  //!< first node of the stencil per axis
};

template <int D, class Kernel>
inline StencilAnchor<D> stencil_anchor(const Kernel& kernel, const Grid<D>& grid, const Vec<D>& x) {
  const Vec<D> xi = grid.to_cell_units(x);
  StencilAnchor<D> a;
  for (int d = 0; d < D; ++d) {
    a.xi[d] = xi[d];
    a.first[d] = kernel.first(xi[d]);
  }
  return a;
}

//! The stencil of an anchor.
template <int D, class Kernel>
[[gnu::always_inline]] inline void expand_stencil(const Kernel& kernel, const Grid<D>& grid,
                                                  const StencilAnchor<D>& a,
                                                  Stencil<D, Kernel>& s) {
  const double inv_h = grid.inverse_cell();
  IVec<D> first;
  for (int d = 0; d < D; ++d) {
    first[d] = a.first[d];
    kernel.weights(a.xi[d], a.first[d], s.w[d], s.dw[d]);
    s.offset[d] = a.first[d] - a.xi[d];
    for (int b = 0; b < Kernel::width; ++b) s.dw[d][b] *= inv_h;
  }
  s.base = grid.flatten(first);
}

//! Fill the stencil of a point at x.
template <int D, class Kernel>
inline void compute_stencil(const Kernel& kernel, const Grid<D>& grid, const Vec<D>& x,
                            Stencil<D, Kernel>& s) {
  expand_stencil(kernel, grid, stencil_anchor(kernel, grid, x), s);
}

//! Visit every node of a stencil: f(node, N, ∇N, a) where a is the node's offset within the
//! stencil in cells (for x_i − x_p = (offset + a) h). Fully inlined for a compile-time kernel.
template <int D, class Kernel, class F>
inline void for_each_node(const Stencil<D, Kernel>& s,
                          const std::type_identity_t<std::array<long, D>>& strides, F&& f) {
  constexpr int W = Kernel::width;
  if constexpr (D == 2) {
    for (int b = 0; b < W; ++b) {
      const long row = s.base + b * strides[1];
      for (int a = 0; a < W; ++a) {
        const double N = s.w[0][a] * s.w[1][b];
        const Vec<2> grad(s.dw[0][a] * s.w[1][b], s.w[0][a] * s.dw[1][b]);
        f(row + a, N, grad, IVec<2>(a, b));
      }
    }
  } else {
    for (int c = 0; c < W; ++c) {
      for (int b = 0; b < W; ++b) {
        const long row = s.base + b * strides[1] + c * strides[2];
        const double wbc = s.w[1][b] * s.w[2][c];
        for (int a = 0; a < W; ++a) {
          const double N = s.w[0][a] * wbc;
          const Vec<3> grad(s.dw[0][a] * wbc, s.w[0][a] * s.dw[1][b] * s.w[2][c],
                            s.w[0][a] * s.w[1][b] * s.dw[2][c]);
          f(row + a, N, grad, IVec<3>(a, b, c));
        }
      }
    }
  }
}

//! One row of a stencil: its nodes along axis 0 at a fixed offset (b[, c]) on the other axes.
//! Node a of the row has the weight N = w[0][a]·weight and the gradient
//! ∇N = (dw[0][a]·weight, w[0][a]·grad[1][, w[0][a]·grad[2]]): the tensor product split into
//! its axis-0 factor and the rest, so a transfer sums a row with the 1D weights of axis 0 and
//! folds in the rest once per row (docs/theory/performance.md, "Rows").
template <int D>
struct StencilRow {
  long first;      //!< flat index of the row's node a = 0
  int index[D];    //!< that node's offset within the stencil: (0, b[, c])
  double weight;   //!< Π_{e>0} φ_e
  double grad[D];  //!< grad[e] = (dφ_e/dx) Π_{f>0, f≠e} φ_f for e > 0; grad[0] = 0
};

//! Visit every row of a stencil: f(row). Fully inlined for a compile-time kernel.
template <int D, class Kernel, class F>
inline void for_each_row(const Stencil<D, Kernel>& s,
                         const std::type_identity_t<std::array<long, D>>& strides, F&& f) {
  constexpr int W = Kernel::width;
  if constexpr (D == 2) {
    for (int b = 0; b < W; ++b)
      f(StencilRow<2>{s.base + b * strides[1], {0, b}, s.w[1][b], {0.0, s.dw[1][b]}});
  } else {
    for (int c = 0; c < W; ++c)
      for (int b = 0; b < W; ++b)
        f(StencilRow<3>{s.base + b * strides[1] + c * strides[2],
                        {0, b, c},
                        s.w[1][b] * s.w[2][c],
                        {0.0, s.dw[1][b] * s.w[2][c], s.w[1][b] * s.dw[2][c]}});
  }
}

//! Row blocks: the W nodes of a stencil row are consecutive in storage, so their values of a
//! nodal vector field are K = W·D consecutive doubles (node a, component i at a·D + i). A
//! gather sums whole blocks over the rows, each scaled by a per-row factor, and contracts the
//! sum with the 1D weights of axis 0 once per point; in 3D, with W ≥ 3, it sums each plane of
//! the stencil first (sum_rows; docs/theory/performance.md, "Rows"). The
//! block sums run on short vectors (GCC/Clang vector extensions): four lanes where the build
//! has AVX, then two lanes (SSE2, NEON), then one double, so a block of nine doubles is two
//! four-lane vectors and a double. Each lane sums its own element over the rows in row order,
//! so the lane widths do not change the results. One sum at a time runs over all rows so its
//! accumulators stay in registers. These helpers and expand_stencil are always inlined: in
//! the large loop bodies of the transfers GCC's inliner otherwise left some of them as calls,
//! with their arrays passed through memory.
template <int D>
inline const double* row_block(const std::vector<Vec<D>>& field, long first) {
  static_assert(sizeof(Vec<D>) == D * sizeof(double), "node vectors must be packed");
  return field[first].data();
}

using DoublePair = double __attribute__((vector_size(16)));
#if defined(__AVX__)
using DoubleQuad = double __attribute__((vector_size(32)));
inline constexpr bool kQuadLanes = true;
#else
using DoubleQuad = DoublePair;  // unused: no four-lane vectors without AVX
inline constexpr bool kQuadLanes = false;
#endif

//! A block of K doubles split into lanes: `quads` four-lane vectors, then `pairs` two-lane
//! vectors, then `single` doubles (0 or 1).
template <int K>
struct BlockLanes {
  static constexpr int quads = kQuadLanes ? K / 4 : 0;
  static constexpr int pairs = (K - 4 * quads) / 2;
  static constexpr int pair_start = 4 * quads;
  static constexpr int single = K - 4 * quads - 2 * pairs;
};

template <class V>
[[gnu::always_inline]] inline V load_lanes(const double* p) {
  V r;
  std::memcpy(&r, p, sizeof r);
  return r;
}
template <class V>
[[gnu::always_inline]] inline void store_lanes(double* p, V v) {
  std::memcpy(p, &v, sizeof v);
}

//! sum = Σ_r factor(r) · blocks[r], over R blocks of K doubles.
template <int K, int R, class Factor>
[[gnu::always_inline]] inline void sum_blocks(const double* const (&blocks)[R], Factor&& factor,
                                              double (&sum)[K]) {
  using L = BlockLanes<K>;
  DoubleQuad quads[L::quads + 1];  // + 1: no zero-length arrays
  DoublePair pairs[L::pairs + 1];
  double single = 0.0;
  for (int j = 0; j < L::quads; ++j) quads[j] = DoubleQuad{};
  for (int j = 0; j < L::pairs; ++j) pairs[j] = DoublePair{};
  for (int r = 0; r < R; ++r) {
    const double f = factor(r);
    for (int j = 0; j < L::quads; ++j) quads[j] += f * load_lanes<DoubleQuad>(blocks[r] + 4 * j);
    for (int j = 0; j < L::pairs; ++j)
      pairs[j] += f * load_lanes<DoublePair>(blocks[r] + L::pair_start + 2 * j);
    if constexpr (L::single == 1) single += f * blocks[r][K - 1];
  }
  for (int j = 0; j < L::quads; ++j) store_lanes(sum + 4 * j, quads[j]);
  for (int j = 0; j < L::pairs; ++j) store_lanes(sum + L::pair_start + 2 * j, pairs[j]);
  if constexpr (L::single == 1) sum[K - 1] = single;
}

//! target[k] += Σ_j c[j] · blocks[j][k] for k < K: a row's share of a scatter, a combination
//! of per-point blocks with the row's factors, added to the row's nodes.
template <int K, int J>
[[gnu::always_inline]] inline void add_combination(double* target, const double (&c)[J],
                                                   const double (&blocks)[J][K]) {
  using L = BlockLanes<K>;
  const auto add = [&]<class V>(int k, V) {
    V sum = c[0] * load_lanes<V>(blocks[0] + k);
    for (int i = 1; i < J; ++i) sum += c[i] * load_lanes<V>(blocks[i] + k);
    store_lanes(target + k, load_lanes<V>(target + k) + sum);
  };
  for (int j = 0; j < L::quads; ++j) add(4 * j, DoubleQuad{});
  for (int j = 0; j < L::pairs; ++j) add(L::pair_start + 2 * j, DoublePair{});
  if constexpr (L::single == 1) {
    double sum = 0.0;
    for (int i = 0; i < J; ++i) sum += c[i] * blocks[i][K - 1];
    target[K - 1] += sum;
  }
}

//! out[k] = Σ_j c[j] · blocks[j][k] for k < K, the terms added in order of j: a combination of
//! blocks kept for several rows of a scatter.
template <int K, int J>
[[gnu::always_inline]] inline void combine_blocks(double (&out)[K], const double (&c)[J],
                                                  const double* const (&blocks)[J]) {
  using L = BlockLanes<K>;
  const auto combine = [&]<class V>(int k, V) {
    V sum = c[0] * load_lanes<V>(blocks[0] + k);
    for (int i = 1; i < J; ++i) sum += c[i] * load_lanes<V>(blocks[i] + k);
    store_lanes(out + k, sum);
  };
  for (int j = 0; j < L::quads; ++j) combine(4 * j, DoubleQuad{});
  for (int j = 0; j < L::pairs; ++j) combine(L::pair_start + 2 * j, DoublePair{});
  if constexpr (L::single == 1) combine(K - 1, 0.0);
}

//! out_i = Σ_a weights[a] · block[a·D + i]: a summed block contracted along axis 0.
template <int D, int W>
[[gnu::always_inline]] inline void contract_block(const double (&block)[W * D],
                                                  const double (&weights)[W], double (&out)[D]) {
  if constexpr (D == 3 && W == 3 && kQuadLanes) {
    // The block as sum_blocks stores it, two four-lane vectors and a double, contracted in
    // registers. Loads of the triples at offsets 3 and 6 would each span two of those stores,
    // which the store buffer cannot forward: the load waits until both reach the cache. Lane i
    // sums (w0·b_i + w1·b_{3+i}) + w2·b_{6+i}, in the order of the loop below.
    const DoubleQuad x =
        load_lanes<DoubleQuad>(block) * DoubleQuad{weights[0], weights[0], weights[0], weights[1]};
    const DoubleQuad y = load_lanes<DoubleQuad>(block + 4) *
                         DoubleQuad{weights[1], weights[1], weights[2], weights[2]};
    const DoubleQuad z{weights[2] * block[8], 0.0, 0.0, 0.0};
    const DoubleQuad sum =
        x + __builtin_shufflevector(x, y, 3, 4, 5, 6) + __builtin_shufflevector(y, z, 2, 3, 4, 5);
    for (int i = 0; i < D; ++i) out[i] = sum[i];
    return;
  }
  for (int i = 0; i < D; ++i) out[i] = weights[0] * block[i];
  for (int a = 1; a < W; ++a)
    for (int i = 0; i < D; ++i) out[i] += weights[a] * block[a * D + i];
}

//! A gather's sums over the rows of a stencil, for a nodal vector field f (per row, the block
//! f_row of its W nodes): each a block of K = W·D doubles, to contract along axis 0
//! (contract_block).
template <int D, int W>
struct RowSums {
  static constexpr int K = W * D;
  double value[K];     //!< Σ_rows weight · f_row
  double index[D][K];  //!< e > 0: Σ_rows index_e · weight · f_row (with Index)
  double grad[D][K];   //!< e > 0: Σ_rows grad_e · f_row (with Grad)
};

//! The row sums of `field` over the stencil s. A row's factors are products of one factor per
//! axis e > 0: weight = φ₁(b)[·φ₂(c)]. With three or more nodes per axis the 3D sums go plane by
//! plane, over b within each plane c of the stencil, then over c:
//!   value    = Σ_c φ₂(c) P_c,   P_c = Σ_b φ₁(b) f_bc,
//!   index[1] = Σ_c φ₂(c) Q_c,   Q_c = Σ_b b φ₁(b) f_bc,    index[2] = Σ_c c φ₂(c) P_c,
//!   grad[1]  = Σ_c φ₂(c) G_c,   G_c = Σ_b φ₁'(b) f_bc,     grad[2]  = Σ_c φ₂'(c) P_c.
//! For the quadratic kernel with both index and grad that is 14 sums of three blocks where row
//! by row it is 5 sums of nine, and each sum's chain of additions is three long instead of
//! nine. Otherwise (2D, the 3D linear kernel) the sums run row by row, each over all W^(D−1) rows.
template <bool Index, bool Grad, int D, class Kernel>
[[gnu::always_inline]] inline void sum_rows(
    const Stencil<D, Kernel>& s, const std::type_identity_t<std::array<long, D>>& strides,
    const std::type_identity_t<std::vector<Vec<D>>>& field, RowSums<D, Kernel::width>& out) {
  constexpr int W = Kernel::width, K = W * D;
  if constexpr (D == 3 && W >= 3) {
    double P[W][K], Q[W][K], G[W][K];
    const double *p_planes[W], *q_planes[W], *g_planes[W];
    for (int c = 0; c < W; ++c) {
      const double* rows[W];
      for (int b = 0; b < W; ++b)
        rows[b] = row_block(field, s.base + b * strides[1] + c * strides[2]);
      sum_blocks(
          rows, [&](int b) { return s.w[1][b]; }, P[c]);
      if constexpr (Index)
        sum_blocks(
            rows, [&](int b) { return b * s.w[1][b]; }, Q[c]);
      if constexpr (Grad)
        sum_blocks(
            rows, [&](int b) { return s.dw[1][b]; }, G[c]);
      p_planes[c] = P[c], q_planes[c] = Q[c], g_planes[c] = G[c];
    }
    const auto phi2 = [&](int c) { return s.w[2][c]; };
    sum_blocks(p_planes, phi2, out.value);
    if constexpr (Index) {
      sum_blocks(q_planes, phi2, out.index[1]);
      sum_blocks(
          p_planes, [&](int c) { return c * s.w[2][c]; }, out.index[2]);
    }
    if constexpr (Grad) {
      sum_blocks(g_planes, phi2, out.grad[1]);
      sum_blocks(
          p_planes, [&](int c) { return s.dw[2][c]; }, out.grad[2]);
    }
  } else {
    constexpr int R = D == 2 ? W : W * W;
    const double* rows[R];
    double weight[R], index[D][R], grad[D][R];
    for (int r = 0; r < R; ++r) {
      const int b = r % W, c = r / W;  // c = 0 in 2D
      if constexpr (D == 2) {
        rows[r] = row_block(field, s.base + b * strides[1]);
        weight[r] = s.w[1][b];
        grad[1][r] = s.dw[1][b];
      } else {
        rows[r] = row_block(field, s.base + b * strides[1] + c * strides[2]);
        weight[r] = s.w[1][b] * s.w[2][c];
        grad[1][r] = s.dw[1][b] * s.w[2][c];
        grad[2][r] = s.w[1][b] * s.dw[2][c];
        index[2][r] = c * weight[r];
      }
      index[1][r] = b * weight[r];
    }
    sum_blocks(
        rows, [&](int r) { return weight[r]; }, out.value);
    for (int e = 1; e < D; ++e) {
      if constexpr (Index)
        sum_blocks(
            rows, [&](int r) { return index[e][r]; }, out.index[e]);
      if constexpr (Grad)
        sum_blocks(
            rows, [&](int r) { return grad[e][r]; }, out.grad[e]);
    }
  }
}

}  // namespace pellicle
