// The row-block helpers of the transfers (shape/stencil.hpp) split a block of K doubles into
// four-lane, two-lane and single lanes. Whatever the split, each element must be the sum a
// scalar loop gives, term for term in the same order: bitwise, for every block width the
// kernels use (K = W·D: 4, 6, 8, 9, 12).
#include <gtest/gtest.h>

#include <random>

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

}  // namespace
}  // namespace pellicle
