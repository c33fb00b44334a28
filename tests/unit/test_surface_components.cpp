// Connected parts of a cloud (surface/components.hpp): points within h of each other are
// linked; a sphere is one part, two spheres 3 h apart are two, and a third sphere touching
// the second (within h) joins it.
#include <gtest/gtest.h>

#include "pellicle/surface/components.hpp"
#include "support/test_clouds.hpp"

namespace pellicle {
namespace {

constexpr double kH = 0.3;

//! The sphere's points moved by `shift`, appended to `cloud`.
void append_sphere(PointCloud<3>& cloud, const Vec3& shift) {
  const PointCloud<3> sphere = test::jittered_sphere(1.0, kH);
  for (const auto& x : sphere.position) cloud.add_point(x + shift, kH, false);
}

int parts_of(const PointCloud<3>& cloud) {
  NeighbourSearch<3> search;
  NeighbourLists lists;
  search.find(cloud, lists, 1.0, 0);
  return connected_parts(lists);
}

TEST(SurfaceComponents, SpheresApartAreSeparateParts) {
  PointCloud<3> cloud;
  EXPECT_EQ(parts_of(cloud), 0);
  append_sphere(cloud, Vec3::Zero());
  EXPECT_EQ(parts_of(cloud), 1);
  append_sphere(cloud, Vec3(2.0 + 3.0 * kH, 0.0, 0.0));  // gap 3 h
  EXPECT_EQ(parts_of(cloud), 2);
  append_sphere(cloud, Vec3(2.0 + 3.0 * kH + 2.0 - 0.5 * kH, 0.0, 0.0));  // 0.5 h into the 2nd
  EXPECT_EQ(parts_of(cloud), 2);
}

}  // namespace
}  // namespace pellicle
