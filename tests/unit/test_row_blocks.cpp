// The row-block helpers of the transfers (shape/stencil.hpp) split a block of K doubles into
// four-lane, two-lane and single lanes. Whatever the split, each element must be the sum a
// scalar loop gives, term for term in the same order: bitwise, for every block width the
// kernels use (K = W·D: 4, 6, 8, 9, 12). The row sums of a gather must be the sums over the
// stencil's rows with the product factors: bitwise where they go row by row, to round-off where
// they go plane by plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "pellicle/mpm/shape/kernels.hpp"
#include "pellicle/mpm/shape/stencil.hpp"

namespace pellicle {
namespace {

// The split covers every element once (checked when this file compiles).
static_assert(4 * BlockLanes<9>::quads + 2 * BlockLanes<9>::pairs + BlockLanes<9>::single == 9);
static_assert(4 * BlockLanes<6>::quads + 2 * BlockLanes<6>::pairs + BlockLanes<6>::single == 6);

template <int K, int R>
void check_sum_blocks() {
  std::mt19937 rng(K * 100 + R);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double storage[R][K], factors[R];
  const double* blocks[R];
  for (int r = 0; r < R; ++r) {
    for (int k = 0; k < K; ++k) storage[r][k] = u(rng);
    factors[r] = u(rng);
    blocks[r] = storage[r];
  }
  double sum[K];
  sum_blocks(
      blocks, [&](int r) { return factors[r]; }, sum);
  for (int k = 0; k < K; ++k) {
    double expected = 0.0;
    for (int r = 0; r < R; ++r) expected += factors[r] * storage[r][k];
    EXPECT_EQ(sum[k], expected) << "K = " << K << ", R = " << R << ", element " << k;
  }
}

template <int K, int J>
void check_add_combination() {
  std::mt19937 rng(K * 10 + J);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double blocks[J][K], c[J], target[K], expected[K];
  for (int j = 0; j < J; ++j) {
    c[j] = u(rng);
    for (int k = 0; k < K; ++k) blocks[j][k] = u(rng);
  }
  for (int k = 0; k < K; ++k) target[k] = expected[k] = u(rng);
  add_combination(target, c, blocks);
  for (int k = 0; k < K; ++k) {
    double sum = c[0] * blocks[0][k];
    for (int j = 1; j < J; ++j) sum += c[j] * blocks[j][k];
    expected[k] += sum;
    EXPECT_EQ(target[k], expected[k]) << "K = " << K << ", J = " << J << ", element " << k;
  }
}

TEST(RowBlocks, SumsEqualTheScalarLoopBitwise) {
  check_sum_blocks<4, 2>();    // 2D linear: W = 2, two rows
  check_sum_blocks<6, 3>();    // 2D quadratic
  check_sum_blocks<8, 4>();    // 2D cubic
  check_sum_blocks<6, 4>();    // 3D linear
  check_sum_blocks<9, 9>();    // 3D quadratic
  check_sum_blocks<12, 16>();  // 3D cubic
}

TEST(RowBlocks, CombinationsEqualTheScalarLoopBitwise) {
  check_add_combination<4, 1>();
  check_add_combination<4, 2>();
  check_add_combination<6, 3>();
  check_add_combination<8, 2>();
  check_add_combination<9, 3>();
  check_add_combination<12, 3>();
}

template <int D, int W>
void check_contract_block() {
  std::mt19937 rng(D * 10 + W);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double block[W * D], weights[W], out[D];
  for (double& b : block) b = u(rng);
  for (double& w : weights) w = u(rng);
  contract_block<D, W>(block, weights, out);
  for (int i = 0; i < D; ++i) {
    double expected = weights[0] * block[i];
    for (int a = 1; a < W; ++a) expected += weights[a] * block[a * D + i];
    EXPECT_EQ(out[i], expected) << "D = " << D << ", W = " << W << ", component " << i;
  }
}

TEST(RowBlocks, ContractionsEqualTheScalarLoopBitwise) {
  check_contract_block<2, 2>();
  check_contract_block<2, 3>();
  check_contract_block<3, 2>();
  check_contract_block<3, 3>();
  check_contract_block<3, 4>();
}

// Row sums of a random nodal field with random 1D factors, against the sums over the rows with
// each row's factor formed as the product of its axes' factors. `bitwise`: the row-by-row path
// must give exactly these; otherwise they must agree to a few ulps of the sum of magnitudes.
template <int D, class Kernel>
void check_row_sums(bool bitwise) {
  constexpr int W = Kernel::width, K = W * D;
  std::mt19937 rng(D * 100 + W);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<long, D> strides{1, 7};
  if constexpr (D == 3) strides[2] = 56;
  std::vector<Vec<D>> field(7 * 8 * (D == 3 ? 9 : 1));
  for (Vec<D>& f : field)
    for (int i = 0; i < D; ++i) f[i] = u(rng);
  Stencil<D, Kernel> s{};
  s.base = strides[1] + 2 + (D == 3 ? strides[2] : 0);
  for (int d = 0; d < D; ++d)
    for (int a = 0; a < W; ++a) s.w[d][a] = u(rng), s.dw[d][a] = u(rng);
  RowSums<D, W> sums;
  sum_rows<true, true>(s, strides, field, sums);
  const int planes = D == 3 ? W : 1;
  for (int e = 0; e < D; ++e) {  // e = 0: value; e > 0: index[e] and grad[e]
    for (int k = 0; k < K; ++k) {
      double value = 0.0, index = 0.0, grad = 0.0, magnitude = 0.0;
      for (int c = 0; c < planes; ++c)
        for (int b = 0; b < W; ++b) {
          const double f = field[s.base + b * strides[1] + (D == 3 ? c * strides[2] : 0)].data()[k];
          const double phi2 = D == 3 ? s.w[2][c] : 1.0;
          const double weight = D == 3 ? s.w[1][b] * phi2 : s.w[1][b];
          const int index_e = e == 1 ? b : c;
          const double grad_e = e == 1 ? (D == 3 ? s.dw[1][b] * phi2 : s.dw[1][b])
                                       : s.w[1][b] * (D == 3 ? s.dw[2][c] : 0.0);
          value += weight * f;
          index += index_e * weight * f;
          grad += grad_e * f;
          magnitude += std::abs(f) * (std::abs(weight) * (1 + index_e) + std::abs(grad_e));
        }
      const double tolerance =
          bitwise ? 0.0 : 8.0 * std::numeric_limits<double>::epsilon() * magnitude;
      const auto where = [&] {
        return "D = " + std::to_string(D) + ", W = " + std::to_string(W) +
               ", e = " + std::to_string(e) + ", element " + std::to_string(k);
      };
      if (e == 0) {
        EXPECT_NEAR(sums.value[k], value, tolerance) << where();
      } else {
        EXPECT_NEAR(sums.index[e][k], index, tolerance) << "index, " << where();
        EXPECT_NEAR(sums.grad[e][k], grad, tolerance) << "grad, " << where();
      }
    }
  }
}

TEST(RowBlocks, RowSumsAreTheSumsOverTheStencilsRows) {
  check_row_sums<2, shape::Linear>(true);
  check_row_sums<2, shape::QuadraticBSpline>(true);
  check_row_sums<2, shape::CubicBSpline>(true);
  check_row_sums<3, shape::Linear>(true);
  check_row_sums<3, shape::QuadraticBSpline>(false);  // plane by plane
  check_row_sums<3, shape::CubicBSpline>(false);
}

}  // namespace
}  // namespace pellicle
