// The MPI layer of distributed runs, run by ctest under mpirun with 1, 2 and 3 ranks: the
// reductions give every rank the same values, and every rank computes the same patches,
// which together hold every point once.
#include <gtest/gtest.h>

#include "pellicle/dist/decomposition.hpp"
#include "world.hpp"

namespace pellicle {
namespace {

TEST(Communicator, SumsInRankOrderAreTheSameOnEveryRank) {
  const int n = world->size();
  // Terms whose sum depends on the order they are added in: 1, then 1e-16 per rank.
  std::vector<double> values = {world->rank() == 0 ? 1.0 : 1e-16, 1.0 + world->rank()};
  world->sum_in_rank_order(values);
  double expected = 1.0;
  for (int r = 1; r < n; ++r) expected += 1e-16;
  EXPECT_EQ(values[0], expected);
  EXPECT_EQ(values[1], n + n * (n - 1) / 2.0);
  EXPECT_EQ(world->max(values[0]), world->min(values[0]));  // bitwise the same everywhere
}

TEST(Communicator, EveryRankComputesTheSamePatchesAndTheyHoldEveryPointOnce) {
  CellCounts<2> counts{{48, 32}, std::vector<long>(48 * 32)};
  long total = 0;
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 48; ++i) total += counts.points[j * 48 + i] = (i * 7 + j * 3) % 5;
  const auto patches = bisect_patches(counts, world->size(), 2);
  ASSERT_EQ(static_cast<int>(patches.size()), world->size());
  const auto& mine = patches[world->rank()];
  long held = 0;
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 48; ++i)
      if (mine.contains(IVec<2>(i, j))) held += counts.points[j * 48 + i];
  EXPECT_EQ(held, mine.points);
  std::vector<long> sum = {held, mine.lower[0] + 1000L * mine.lower[1]};
  world->sum(sum);
  EXPECT_EQ(sum[0], total);
  long corners = 0;  // every rank's view of the patches agrees with the others'
  for (const auto& p : patches) corners += p.lower[0] + 1000L * p.lower[1];
  EXPECT_EQ(sum[1], corners);
}

}  // namespace
}  // namespace pellicle
