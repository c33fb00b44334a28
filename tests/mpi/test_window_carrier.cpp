// Node states carried between grid storages (dist/window_carrier.hpp): from the whole grid into
// a window, each window node takes its own node's value; from the ranks' windows back to the
// whole grid, each node takes the value of the rank that owns it.
#include <gtest/gtest.h>

#include <vector>

#include "pellicle/dist/window_carrier.hpp"
#include "world.hpp"

namespace pellicle {
namespace {

//! A node's index in the whole grid's storage (ghosts included, axis 0 fastest).
long whole_index(const Grid<2>& grid, long n) {
  const IVec<2> index = grid.unflatten(n);
  return index[1] * (grid.cells()[0] + 1 + 2 * Grid<2>::kGhost) + index[0];
}

TEST(WindowCarrier, AWindowTakesItsNodesValuesFromTheWholeGrid) {
  const Grid<2> whole(Vec2(0, 0), Vec2(2, 1), 0.1, FaceConditions<2>{});
  const Grid<2> shape = Grid<2>::without_storage(Vec2(0, 0), Vec2(2, 1), 0.1, FaceConditions<2>{});
  ASSERT_EQ(shape.node_count(), whole.node_count());
  const Grid<2> window = whole.window({3, 2}, {11, 9}, {4, 3}, {10, 8});
  std::vector<double> values(whole.node_count());
  for (long n = 0; n < whole.node_count(); ++n) values[n] = 0.5 + n;  // each node's own value
  for (const Grid<2>* before : {&whole, &shape}) {
    std::vector<double> carried = values;
    WindowCarrier<2>(*before, window, nullptr).carry(carried);
    ASSERT_EQ(static_cast<long>(carried.size()), window.node_count());
    for (long n = 0; n < window.node_count(); ++n)
      EXPECT_EQ(carried[n], 0.5 + whole_index(window, n)) << "window node " << n;
    std::vector<double> none;  // no state yet: zeros
    WindowCarrier<2>(*before, window, nullptr).carry(none);
    EXPECT_EQ(none, std::vector<double>(window.node_count(), 0.0));
  }
}

TEST(WindowCarrier, TheWholeGridTakesEachNodeFromItsOwner) {
  // Rank r owns the columns [10 r, 10 (r + 1)) of nodes (the last rank the rest) and stores
  // one more column on each side.
  const Grid<2> whole(Vec2(0, 0), Vec2(4, 1), 0.1, FaceConditions<2>{});
  const int ranks = world->size(), me = world->rank();
  const int columns = whole.cells()[0] + 1 + 2 * Grid<2>::kGhost, rows = whole.nodes()[1];
  const int first = me * columns / ranks, last = (me + 1) * columns / ranks - 1;
  const Grid<2> window =
      whole.window({std::max(first - 1, 0), 0}, {std::min(last + 1, columns - 1), rows - 1},
                   {first, 0}, {last, rows - 1});
  std::vector<double> values(window.node_count());
  for (long n = 0; n < window.node_count(); ++n)
    values[n] = window.owns(n) ? 0.5 + whole_index(window, n) : -1.0;  // -1: not its own
  WindowCarrier<2>(window, *world).carry(values);
  ASSERT_EQ(static_cast<long>(values.size()), whole.node_count());
  for (long n = 0; n < whole.node_count(); ++n) EXPECT_EQ(values[n], 0.5 + n) << "node " << n;
}

}  // namespace
}  // namespace pellicle
