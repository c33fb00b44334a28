// Cell grouping of points (pointcloud/, the local normal constructions' first step): groups
// hold the points of their cell, a place maps to the cell the grouping numbers it by, and a
// point whose cell cannot be numbered is refused, not cast.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "pellicle/pointcloud/cell_groups.hpp"

namespace pellicle {
namespace {

TEST(CellGroups, GroupsHoldThePointsOfTheirCell) {
  const std::vector<Vec2> x = {{0.05, 0.05}, {0.15, 0.05}, {0.06, 0.09}, {-0.05, 0.02}};
  const CellGroups<2> groups(x, 0, 4, Vec2::Zero(), 0.1);
  EXPECT_EQ(groups.size(), 3);
  EXPECT_EQ(groups.count_in(IVec<2>(0, 0)), 2);
  EXPECT_EQ(groups.count_in(IVec<2>(1, 0)), 1);
  EXPECT_EQ(groups.count_in(IVec<2>(-1, 0)), 1);
  EXPECT_EQ(groups.count_in(IVec<2>(0, 1)), 0);
}

TEST(CellGroups, PlacesMapToTheCellsOfAShiftedGrid) {
  const std::vector<Vec2> x = {{0.12, 0.31}, {-0.07, 0.02}};
  const CellGroups<2> groups(x, 0, 2, Vec2(0.05, -0.05), 0.1);
  EXPECT_EQ(groups.cell_of(x[0]), IVec<2>(0, 3));
  EXPECT_EQ(groups.cell_of(x[1]), IVec<2>(-2, 0));
  EXPECT_EQ(groups.find(groups.cell_of(x[1])), groups.find(IVec<2>(-2, 0)));
  EXPECT_GE(groups.find(IVec<2>(-2, 0)), 0);
}

TEST(CellGroups, PointsWhoseCellCannotBeNumberedAreRefused) {
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity(), 1e300, -2e8}) {
    const std::vector<Vec2> x = {{0.05, 0.05}, {0.1, bad}};
    EXPECT_THROW(CellGroups<2>(x, 0, 2, Vec2::Zero(), 0.1), std::invalid_argument) << bad;
  }
  const std::vector<Vec2> x = {{0.05, 0.05}, {0.1, 1e7}};  // 1e8 cells: numbered
  EXPECT_EQ(CellGroups<2>(x, 0, 2, Vec2::Zero(), 0.1).size(), 2);
}

}  // namespace
}  // namespace pellicle
