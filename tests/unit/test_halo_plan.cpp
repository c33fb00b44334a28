// The shared-node lists of distributed runs (dist/halo_plan.hpp): each rank lists every node
// of its window once for each other rank whose window holds it, and both sides of a pair list
// the same nodes in the same order.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "pellicle/dist/halo_plan.hpp"

namespace pellicle {
namespace {

template <int D>
void check_plan(const IVec<D>& cells, int ranks, int ghost, int reach) {
  long cell_count = 1, node_count = 1;
  for (int d = 0; d < D; ++d) cell_count *= cells[d], node_count *= cells[d] + 1 + 2 * ghost;
  CellCounts<D> counts{cells, std::vector<long>(cell_count, 1)};
  const auto patches = bisect_patches(counts, ranks, ghost);
  // Which ranks' windows hold each node; every node the points can reach (all but the ghost
  // layers beyond `reach`) is in at least one.
  std::vector<std::vector<int>> holders(node_count);
  for (const auto& p : patches)
    for (long n : node_indices(touched_nodes(p, cells, ghost, reach), cells, ghost))
      holders[n].push_back(p.rank);
  const IndexBox<D> reachable{IVec<D>::Constant(-reach), cells + IVec<D>::Constant(reach)};
  for (long n : node_indices(reachable, cells, ghost)) EXPECT_FALSE(holders[n].empty());

  // Every node of the grid is owned by exactly one patch.
  std::vector<int> owners(node_count, 0);
  for (const auto& p : patches)
    for (long n : node_indices(owned_nodes(p, cells, ghost), cells, ghost)) ++owners[n];
  for (long n = 0; n < node_count; ++n) EXPECT_EQ(owners[n], 1) << "node " << n;

  std::vector<std::vector<SharedWith>> plans;
  for (int r = 0; r < ranks; ++r) plans.push_back(halo_plan(patches, cells, ghost, reach, r));
  for (int r = 0; r < ranks; ++r) {
    // Each node of r's window is listed once for each other rank that holds it.
    std::vector<std::set<int>> listed(node_count);
    int previous = -1;
    for (const auto& e : plans[r]) {
      EXPECT_GT(e.rank, previous) << "lowest rank first";
      previous = e.rank;
      EXPECT_TRUE(std::is_sorted(e.indices.begin(), e.indices.end()));
      for (long n : e.indices) EXPECT_TRUE(listed[n].insert(e.rank).second);
      // Both sides list the same nodes.
      const auto& other = plans[e.rank];
      const auto back = std::find_if(other.begin(), other.end(),
                                     [&](const SharedWith& x) { return x.rank == r; });
      ASSERT_NE(back, other.end());
      EXPECT_EQ(e.indices, back->indices);
    }
    for (long n : node_indices(touched_nodes(patches[r], cells, ghost, reach), cells, ghost)) {
      std::set<int> others(holders[n].begin(), holders[n].end());
      others.erase(r);
      EXPECT_EQ(listed[n], others) << "rank " << r << " node " << n;
    }
  }
}

TEST(HaloPlan, OneRankExchangesNothing) {
  const IVec<2> cells(16, 12);
  CellCounts<2> counts{cells, std::vector<long>(16 * 12, 1)};
  EXPECT_TRUE(halo_plan(bisect_patches(counts, 1, 2), cells, 2, 2, 0).empty());
}

TEST(HaloPlan, ListsAgreeBetweenRanksIn2D) {
  check_plan<2>(IVec<2>(24, 16), 2, 2, 2);
  check_plan<2>(IVec<2>(24, 16), 3, 2, 2);
  check_plan<2>(IVec<2>(30, 30), 5, 2, 2);
  check_plan<2>(IVec<2>(30, 30), 5, 2, 1);
}

TEST(HaloPlan, ListsAgreeBetweenRanksIn3D) {
  check_plan<3>(IVec<3>(12, 10, 8), 3, 2, 2);
  check_plan<3>(IVec<3>(16, 16, 16), 8, 2, 1);
}

TEST(HaloPlan, TwoStripsShareFiveColumnsOfNodes) {
  // 20 × 10 cells cut at x = 10. Reaching two layers, rank 0's points reach node columns
  // −2 … 12, rank 1's 8 … 22: they share columns 8–12, each 15 nodes high (10 + 1 cells'
  // nodes and 2 × 2 ghosts).
  const IVec<2> cells(20, 10);
  CellCounts<2> counts{cells, std::vector<long>(200, 1)};
  const auto patches = bisect_patches(counts, 2, 2);
  ASSERT_EQ(patches[0].upper[0], 10);
  const auto plan = halo_plan(patches, cells, 2, 2, 0);
  ASSERT_EQ(plan.size(), 1u);
  EXPECT_EQ(plan[0].rank, 1);
  EXPECT_EQ(plan[0].indices.size(), 5u * 15u);
  // Reaching one layer (the linear kernel): columns 9–11, 13 nodes high (one ghost row each
  // side).
  EXPECT_EQ(halo_plan(patches, cells, 2, 1, 0)[0].indices.size(), 3u * 13u);
  EXPECT_THROW(halo_plan(patches, cells, 2, 2, 2), std::invalid_argument);
}

TEST(HaloPlan, TwoStripsShareTheCellsAroundTheirCut) {
  // Cut at x = 10, reaching one node layer: rank 0 holds cell columns 0 … 11 (its points'
  // spread reaches column 10, the nodes of its window, up to column 11, read columns 10 and
  // 11), rank 1 columns 8 … 19. They share columns 8–11, all 10 cells high, listed alike.
  const IVec<2> cells(20, 10);
  CellCounts<2> counts{cells, std::vector<long>(200, 1)};
  const auto patches = bisect_patches(counts, 2, 2);
  const auto mine = shared_cells(patches, cells, 1, 0), theirs = shared_cells(patches, cells, 1, 1);
  ASSERT_EQ(mine.size(), 1u);
  ASSERT_EQ(theirs.size(), 1u);
  EXPECT_EQ(mine[0].rank, 1);
  EXPECT_EQ(mine[0].indices, theirs[0].indices);
  ASSERT_EQ(mine[0].indices.size(), 4u * 10u);
  EXPECT_EQ(mine[0].indices.front(), 8);
  EXPECT_EQ(mine[0].indices.back(), 9 * 20 + 11);
}

}  // namespace
}  // namespace pellicle
