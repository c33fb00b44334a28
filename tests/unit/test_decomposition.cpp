// Patch decomposition by recursive bisection of point counts (dist/decomposition.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

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

//! The bisection as a plain recursion over the cells' counts, depth first: the reference the
//! level-by-level split must reproduce patch for patch.
template <int D>
void reference_bisect(const CellCounts<D>& counts, const IVec<D>& lower, const IVec<D>& upper,
                      int ranks, int first_rank, int min_cells, std::vector<Patch<D>>& out) {
  auto plane_sums = [&](int axis) {
    std::vector<double> sums(upper[axis] - lower[axis], 0.0);
    IVec<D> cell = lower;
    while (true) {
      sums[cell[axis] - lower[axis]] += static_cast<double>(counts.at(cell));
      int d = 0;
      while (d < D && ++cell[d] == upper[d]) cell[d] = lower[d], ++d;
      if (d == D) return sums;
    }
  };
  if (ranks == 1) {
    const auto sums = plane_sums(0);
    out.push_back(
        {lower, upper, first_rank, std::lround(std::accumulate(sums.begin(), sums.end(), 0.0))});
    return;
  }
  int axis = -1;
  for (int d = 0; d < D; ++d)  // the longest extent with room, the lower axis among equals
    if (upper[d] - lower[d] >= 2 * min_cells &&
        (axis < 0 || upper[d] - lower[d] > upper[axis] - lower[axis]))
      axis = d;
  ASSERT_GE(axis, 0);
  const auto sums = plane_sums(axis);
  const double target = std::accumulate(sums.begin(), sums.end(), 0.0) * (ranks / 2) / ranks;
  double below = 0.0, best = 1e300;
  int first = min_cells, last = min_cells;
  for (int cut = 1; cut <= static_cast<int>(sums.size()) - min_cells; ++cut) {
    below += sums[cut - 1];
    if (cut < min_cells) continue;
    const double error = std::abs(below - target);
    if (error < best)
      best = error, first = last = cut;
    else if (error == best && cut == last + 1)
      last = cut;
  }
  IVec<D> middle_upper = upper, middle_lower = lower;
  middle_upper[axis] = middle_lower[axis] = lower[axis] + (first + last) / 2;
  reference_bisect(counts, lower, middle_upper, ranks / 2, first_rank, min_cells, out);
  reference_bisect(counts, middle_lower, upper, ranks - ranks / 2, first_rank + ranks / 2,
                   min_cells, out);
}

//! Clustered random points: counts per cell, and the points' cells one by one.
template <int D>
CellCounts<D> clustered_counts(const IVec<D>& cells, unsigned seed, std::vector<IVec<D>>& points) {
  CellCounts<D> counts = uniform_counts<D>(cells, 0);
  std::mt19937 rng(seed);
  for (int cluster = 0; cluster < 4; ++cluster) {
    Vec<D> centre, spread;
    for (int d = 0; d < D; ++d)
      centre[d] = std::uniform_real_distribution<double>(0, cells[d])(rng),
      spread[d] = std::uniform_real_distribution<double>(0.5, 0.2 * cells[d])(rng);
    for (int k = 0; k < 3000; ++k) {
      IVec<D> cell;
      for (int d = 0; d < D; ++d)
        cell[d] = std::clamp(
            static_cast<int>(std::normal_distribution<double>(centre[d], spread[d])(rng)), 0,
            cells[d] - 1);
      points.push_back(cell);
      long flat = cell[D - 1];
      for (int d = D - 2; d >= 0; --d) flat = flat * cells[d] + cell[d];
      ++counts.points[flat];
    }
  }
  return counts;
}

template <int D>
void expect_same_patches(const std::vector<Patch<D>>& a, const std::vector<Patch<D>>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t r = 0; r < a.size(); ++r) {
    EXPECT_EQ(a[r].lower, b[r].lower) << "patch " << r;
    EXPECT_EQ(a[r].upper, b[r].upper) << "patch " << r;
    EXPECT_EQ(a[r].rank, b[r].rank) << "patch " << r;
    EXPECT_EQ(a[r].points, b[r].points) << "patch " << r;
  }
}

template <int D>
void expect_reference_split(const IVec<D>& cells) {
  for (unsigned seed : {1u, 2u, 3u})
    for (int ranks : {1, 2, 3, 5, 7, 8, 12}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::to_string(ranks) + " ranks");
      std::vector<IVec<D>> points;
      const CellCounts<D> counts = clustered_counts<D>(cells, seed, points);
      std::vector<Patch<D>> reference;
      reference_bisect<D>(counts, IVec<D>::Zero(), cells, ranks, 0, 2, reference);
      expect_same_patches(bisect_patches(counts, ranks, 2), reference);
      // Each point visited by itself, and `sum` doubling every count, as if a second rank
      // held the same points: the patches of the doubled counts.
      auto each = [&](const std::function<void(const IVec<D>&, long)>& visit) {
        for (const auto& cell : points) visit(cell, 1);
      };
      CellCounts<D> doubled = counts;
      for (long& n : doubled.points) n *= 2;
      std::vector<Patch<D>> twice;
      reference_bisect<D>(doubled, IVec<D>::Zero(), cells, ranks, 0, 2, twice);
      expect_same_patches(bisect_patches<D>(cells, ranks, 2, each,
                                            [](std::vector<long>& v) {
                                              for (long& n : v) n *= 2;
                                            }),
                          twice);
    }
}

TEST(Decomposition, LevelByLevelSplitIsTheDepthFirstBisection) {
  expect_reference_split<2>({64, 48});
  expect_reference_split<3>({20, 16, 12});
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
