// Patch decomposition by recursive bisection of point counts (dist/decomposition.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "pellicle/dist/decomposition.hpp"

namespace pellicle {
namespace {

template <int D>
CellCounts<D> uniform_counts(const IVec<D>& cells, long per_cell) {
  long n = 1;
  for (int d = 0; d < D; ++d) n *= cells[d];
  return {cells, std::vector<long>(n, per_cell)};
}

//! Every cell lies in exactly one patch, and the patches' counts add up to the total.
template <int D>
void expect_tiling(const CellCounts<D>& counts, const std::vector<Patch<D>>& patches) {
  long total = 0;
  for (long n : counts.points) total += n;
  long sum = 0;
  for (const auto& p : patches) sum += p.points;
  EXPECT_EQ(sum, total);
  IVec<D> cell = IVec<D>::Zero();
  while (true) {
    int owners = 0;
    for (const auto& p : patches) owners += p.contains(cell);
    ASSERT_EQ(owners, 1);
    int d = 0;
    while (d < D && ++cell[d] == counts.cells[d]) cell[d] = 0, ++d;
    if (d == D) break;
  }
}

TEST(Decomposition, OneRankOwnsTheWholeGrid) {
  const auto counts = uniform_counts<2>({10, 7}, 4);
  const auto patches = bisect_patches(counts, 1, 2);
  ASSERT_EQ(patches.size(), 1u);
  EXPECT_EQ(patches[0].lower, IVec<2>(0, 0));
  EXPECT_EQ(patches[0].upper, IVec<2>(10, 7));
  EXPECT_EQ(patches[0].points, 280);
}

TEST(Decomposition, ThreeRanksOnAUniformGridGetAThirdEach) {
  const auto counts = uniform_counts<2>({60, 30}, 4);
  const auto patches = bisect_patches(counts, 3, 2);
  ASSERT_EQ(patches.size(), 3u);
  expect_tiling(counts, patches);
  // 60 columns: 20 to rank 0, then the other 40 × 30 cut across x again into 20 + 20.
  for (int r = 0; r < 3; ++r) {
    EXPECT_EQ(patches[r].rank, r);
    EXPECT_EQ(patches[r].points, 2400);
  }
  EXPECT_DOUBLE_EQ(imbalance(patches), 0.0);
}

TEST(Decomposition, CutsBalancePointsNotCells) {
  // Two disks of points in opposite corners of a 40 × 40 grid (the two-disk problem): the
  // two ranks get one disk each although the cut is not at the middle column.
  CellCounts<2> counts = uniform_counts<2>({40, 40}, 0);
  auto fill = [&](double cx, double cy, double r, long n) {
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i)
        if (std::hypot(i + 0.5 - cx, j + 0.5 - cy) < r) counts.points[j * 40 + i] = n;
  };
  fill(8.0, 8.0, 7.0, 4);
  fill(28.0, 28.0, 10.0, 4);  // a larger disk: more points on that side
  const auto patches = bisect_patches(counts, 2, 2);
  expect_tiling(counts, patches);
  EXPECT_NE(patches[0].upper[0], 20);  // not the geometric middle
  EXPECT_LT(imbalance(patches), 0.05);
}

TEST(Decomposition, EightRanksSplitACubeIntoOctants) {
  const auto counts = uniform_counts<3>({16, 16, 16}, 1);
  const auto patches = bisect_patches(counts, 8, 2);
  ASSERT_EQ(patches.size(), 8u);
  expect_tiling(counts, patches);
  for (const auto& p : patches) {
    EXPECT_EQ(p.points, 512);
    EXPECT_EQ(p.upper - p.lower, IVec<3>(8, 8, 8));
  }
}

TEST(Decomposition, NoPatchIsNarrowerThanTheHalo) {
  // All the points in one column: a cut there would leave patches one cell wide.
  CellCounts<2> counts = uniform_counts<2>({12, 12}, 0);
  for (int j = 0; j < 12; ++j) counts.points[j * 12 + 5] = 10;
  const auto patches = bisect_patches(counts, 3, 3);
  expect_tiling(counts, patches);
  for (const auto& p : patches)
    for (int d = 0; d < 2; ++d) EXPECT_GE(p.upper[d] - p.lower[d], 3);
}

TEST(Decomposition, TooManyRanksForTheGridIsRefusedWithTheSizes) {
  const auto counts = uniform_counts<2>({6, 6}, 1);
  try {
    bisect_patches(counts, 16, 2);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cells among"), std::string::npos) << e.what();
  }
  EXPECT_THROW(bisect_patches(counts, 0, 2), std::invalid_argument);
}

}  // namespace
}  // namespace pellicle
