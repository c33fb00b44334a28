// The halo exchange lists of distributed runs (dist/halo_plan.hpp): owned nodes partition the
// grid, every halo node is sent to exactly one owner, and what one rank sends is what the
// other expects, node for node.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "pellicle/dist/halo_plan.hpp"

namespace pellicle {
namespace {

template <int D>
void check_plan(const IVec<D>& cells, int ranks, int ghost) {
  long cell_count = 1, node_count = 1;
  for (int d = 0; d < D; ++d) cell_count *= cells[d], node_count *= cells[d] + 1 + 2 * ghost;
  CellCounts<D> counts{cells, std::vector<long>(cell_count, 1)};
  const auto patches = bisect_patches(counts, ranks, ghost);
  // Owned nodes: every node of the grid (ghost layers included) exactly once.
  std::vector<int> owners(node_count, 0);
  for (const auto& p : patches)
    for (long n : node_indices(owned_nodes(p, cells, ghost), cells, ghost)) ++owners[n];
  EXPECT_TRUE(std::all_of(owners.begin(), owners.end(), [](int o) { return o == 1; }));

  std::vector<std::vector<HaloExchange>> plans;
  for (int r = 0; r < ranks; ++r) plans.push_back(halo_plan(patches, cells, ghost, r));
  for (int r = 0; r < ranks; ++r) {
    // The halo (touched, not owned) goes to owners, each node once.
    const auto touched = node_indices(touched_nodes(patches[r], cells, ghost), cells, ghost);
    const auto owned = node_indices(owned_nodes(patches[r], cells, ghost), cells, ghost);
    std::vector<long> halo;
    std::set_difference(touched.begin(), touched.end(), owned.begin(), owned.end(),
                        std::back_inserter(halo));
    std::vector<long> sent;
    for (const auto& e : plans[r]) {
      EXPECT_TRUE(std::is_sorted(e.to_owner.begin(), e.to_owner.end()));
      sent.insert(sent.end(), e.to_owner.begin(), e.to_owner.end());
      // What r sends to s is what s expects from r.
      const auto& other = plans[e.rank];
      const auto back = std::find_if(other.begin(), other.end(),
                                     [&](const HaloExchange& x) { return x.rank == r; });
      ASSERT_NE(back, other.end());
      EXPECT_EQ(e.to_owner, back->from_halo);
      EXPECT_EQ(e.from_halo, back->to_owner);
    }
    std::sort(sent.begin(), sent.end());
    EXPECT_EQ(sent, halo) << "rank " << r;
  }
}

TEST(HaloPlan, OneRankExchangesNothing) {
  const IVec<2> cells(16, 12);
  CellCounts<2> counts{cells, std::vector<long>(16 * 12, 1)};
  EXPECT_TRUE(halo_plan(bisect_patches(counts, 1, 2), cells, 2, 0).empty());
}

TEST(HaloPlan, ListsAgreeBetweenRanksIn2D) {
  check_plan<2>(IVec<2>(24, 16), 2, 2);
  check_plan<2>(IVec<2>(24, 16), 3, 2);
  check_plan<2>(IVec<2>(30, 30), 5, 2);
}

TEST(HaloPlan, ListsAgreeBetweenRanksIn3D) {
  check_plan<3>(IVec<3>(12, 10, 8), 3, 2);
  check_plan<3>(IVec<3>(16, 16, 16), 8, 2);
}

TEST(HaloPlan, TwoStripsShareFourLayersOfNodes) {
  // 20 × 10 cells cut at x = 10. Rank 0 owns node columns −2 … 9 and reaches up to 12;
  // rank 1 owns 10 … 22 and reaches down to 8. So rank 0 sends columns 10–12 to rank 1 and
  // takes back columns 8–9, each column 15 nodes high (10 + 1 cells' nodes and 2 × 2 ghosts).
  const IVec<2> cells(20, 10);
  CellCounts<2> counts{cells, std::vector<long>(200, 1)};
  const auto patches = bisect_patches(counts, 2, 2);
  ASSERT_EQ(patches[0].upper[0], 10);
  const auto plan = halo_plan(patches, cells, 2, 0);
  ASSERT_EQ(plan.size(), 1u);
  EXPECT_EQ(plan[0].to_owner.size(), 3u * 15u);   // columns 10, 11, 12
  EXPECT_EQ(plan[0].from_halo.size(), 2u * 15u);  // columns 8, 9
  EXPECT_THROW(halo_plan(patches, cells, 2, 2), std::invalid_argument);
}

}  // namespace
}  // namespace pellicle
