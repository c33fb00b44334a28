// Regions by inequalities and their boolean combinations, and filling them with points.
#include <gtest/gtest.h>

#include <numbers>

#include "pellicle/geometry/fill.hpp"
#include "pellicle/geometry/region.hpp"

namespace pellicle {
namespace {

TEST(Regions, PrimitiveShapes2D) {
  const auto box = make_box<2>(Vec2(0, 0), Vec2(1, 2));
  EXPECT_TRUE(box->contains(Vec2(0.5, 1.9)));
  EXPECT_FALSE(box->contains(Vec2(1.1, 0.5)));
  const auto disk = make_ball<2>(Vec2(1, 1), 0.5);
  EXPECT_TRUE(disk->contains(Vec2(1.3, 1.3)));
  EXPECT_FALSE(disk->contains(Vec2(1.4, 1.4)));
  const auto ellipse = make_ellipsoid<2>(Vec2(0, 0), Vec2(2, 1));
  EXPECT_TRUE(ellipse->contains(Vec2(1.9, 0.0)));
  EXPECT_FALSE(ellipse->contains(Vec2(0.0, 1.1)));
  const auto half = make_half_space<2>(Vec2(0, 1), Vec2(0, 1));  // y ≤ 1
  EXPECT_TRUE(half->contains(Vec2(100, 0.99)));
  EXPECT_FALSE(half->contains(Vec2(0, 1.01)));
}

TEST(Regions, NonConvexPolygon) {
  // An L shape: the notch [1,2]×[1,2] is outside.
  const auto l_shape =
      make_polygon({Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)});
  EXPECT_TRUE(l_shape->contains(Vec2(0.5, 1.5)));
  EXPECT_TRUE(l_shape->contains(Vec2(1.5, 0.5)));
  EXPECT_FALSE(l_shape->contains(Vec2(1.5, 1.5)));
  EXPECT_TRUE(l_shape->contains(Vec2(2.0, 0.5)));  // boundary counts as inside
}

TEST(Regions, BooleanCombinations3D) {
  std::vector<RegionPtr<3>> parts;
  parts.push_back(make_ball<3>(Vec3::Zero(), 1.0));
  parts.push_back(make_ball<3>(Vec3::Zero(), 0.5));
  const auto shell = make_difference<3>(std::move(parts));
  EXPECT_TRUE(shell->contains(Vec3(0.75, 0, 0)));
  EXPECT_FALSE(shell->contains(Vec3(0.25, 0, 0)));

  std::vector<RegionPtr<3>> lens_parts;
  lens_parts.push_back(make_ball<3>(Vec3(-0.5, 0, 0), 1.0));
  lens_parts.push_back(make_ball<3>(Vec3(0.5, 0, 0), 1.0));
  const auto lens = make_intersection<3>(std::move(lens_parts));
  EXPECT_TRUE(lens->contains(Vec3(0, 0.5, 0)));
  EXPECT_FALSE(lens->contains(Vec3(-1.2, 0, 0)));
  EXPECT_NEAR(lens->bounds().lower.x(), -0.5, 1e-15);

  std::vector<RegionPtr<3>> pair;
  pair.push_back(make_box<3>(Vec3(0, 0, 0), Vec3(1, 1, 1)));
  pair.push_back(make_box<3>(Vec3(2, 0, 0), Vec3(3, 1, 1)));
  const auto both = make_union<3>(std::move(pair));
  EXPECT_TRUE(both->contains(Vec3(2.5, 0.5, 0.5)));
  EXPECT_FALSE(both->contains(Vec3(1.5, 0.5, 0.5)));
}

TEST(Fill, PointsPerCellAndVolume) {
  // A box aligned with the cells holds exactly n² points per cell.
  const auto box = make_box<2>(Vec2(0.2, 0.2), Vec2(0.6, 0.4));
  const auto pts = fill_region<2>(*box, Vec2(0, 0), Vec2(1, 1), 0.1, 3);
  EXPECT_EQ(pts.size(), 4u * 2u * 9u);
  // A disk: point count × sub-cell area approaches the disk area.
  const auto disk = make_ball<2>(Vec2(0.5, 0.5), 0.3);
  const double h = 0.01;
  const auto disk_points = fill_region<2>(*disk, Vec2(0, 0), Vec2(1, 1), h, 2);
  const double area = disk_points.size() * (h / 2) * (h / 2);
  EXPECT_NEAR(area, std::numbers::pi * 0.09, 0.005 * std::numbers::pi * 0.09);
  // Regions reaching outside the grid are clipped to it.
  const auto half = make_half_space<3>(Vec3(0, 0, 0.25), Vec3(0, 0, 1));
  const auto slab = fill_region<3>(*half, Vec3::Zero(), Vec3::Ones(), 0.25, 2);
  EXPECT_EQ(slab.size(), 4u * 4u * 1u * 8u);
}

}  // namespace
}  // namespace pellicle
