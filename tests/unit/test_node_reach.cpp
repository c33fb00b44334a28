// A distributed run's window (dist/) holds the nodes a patch's points reach: Transfer::
// node_reach must cover every node a kernel gives weight to from points anywhere in a box of
// cells, up to its sides, and be no wider than the kernel needs.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <string>

#include "pellicle/mpm/transfer.hpp"

namespace pellicle {
namespace {

TEST(NodeReach, CoversEveryWeightedNodeOfPointsInABoxOfCells) {
  const Grid<2> grid({0.0, 0.0}, {1.0, 1.0}, 0.05, {});
  const IVec<2> lower(6, 5), upper(11, 9);  // the box of cells, in cell-corner coordinates
  const std::map<std::string, int> expected = {
      {"linear", 1}, {"ugimp", 1}, {"quadratic-bspline", 1}, {"cubic-bspline", 2}};
  for (const auto& kernel : kernel_choices<2>()) {
    const auto transfer = kernel.make({}, 2.0);
    const int reach = transfer->node_reach();
    EXPECT_EQ(reach, expected.at(kernel.name)) << kernel.name;
    Particles<2> points;
    points.bodies.push_back({});
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 400; ++k) {
      // Inside the box, a quarter of them on its sides.
      Vec<2> x;
      for (int d = 0; d < 2; ++d) {
        const double side = k % 4 == 0 ? (k % 8 == 0 ? lower[d] : upper[d] - 1e-15) : 0.0;
        const double cell = side != 0.0 ? side : lower[d] + u(random) * (upper[d] - lower[d]);
        x[d] = grid.lower()[d] + cell * grid.cell();
      }
      points.add(x, Vec<2>::Zero(), 1.0, 1.0);
    }
    const int n = transfer->stencil_size();
    std::vector<long> nodes(points.size() * n);
    std::vector<double> weights(nodes.size());
    transfer->node_weights(points, grid, 0, points.size(), nodes.data(), weights.data());
    int widest = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (weights[i] == 0.0) continue;
      const IVec<2> corner = grid.unflatten(nodes[i]) - IVec<2>::Constant(Grid<2>::kGhost);
      for (int d = 0; d < 2; ++d)
        widest = std::max({widest, lower[d] - corner[d], corner[d] - upper[d]});
    }
    EXPECT_LE(widest, reach) << kernel.name;
    EXPECT_GE(widest, reach - 1) << kernel.name;  // one layer is for round-off at the sides
  }
}

}  // namespace
}  // namespace pellicle
