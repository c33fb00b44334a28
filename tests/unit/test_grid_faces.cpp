// The grid's face conditions (user guide, [grid] boundary): on a fixed face the velocity is
// zero, on a slip face only its normal component is, a free face imposes nothing; ghost nodes
// beyond a fixed or slip face are mirror images of the interior (v_ghost = R v_image, R = −I
// or the reflection across the face), and what points scatter onto them folds back into
// their images with Rᵀ. Checked node by node for each condition on the face x = 0.
#include <gtest/gtest.h>

#include <cmath>

#include "pellicle/mpm/grid.hpp"

namespace pellicle {
namespace {

constexpr double kCell = 0.25;

Grid<2> grid_with(FaceCondition x_min) {
  FaceConditions<2> faces;
  faces.fill(FaceCondition::free);
  faces[0] = x_min;
  return Grid<2>(Vec2::Zero(), Vec2::Ones(), kCell, faces);
}

//! R of the condition on x = 0: the ghost's velocity is R times its image's.
Vec2 mirrored(FaceCondition c, const Vec2& v) {
  if (c == FaceCondition::fixed) return -v;
  if (c == FaceCondition::slip) return Vec2(-v.x(), v.y());
  return v;
}

//! The node at the mirror image of `node` across x = 0.
long image_of(const Grid<2>& g, long node) {
  const Vec2 x = g.node_position(node);
  IVec<2> index = g.unflatten(node);
  index[0] += static_cast<int>(std::lround(-2.0 * x.x() / kCell));
  return g.flatten(index);
}

TEST(GridFaces, VelocitiesOnTheFaceAndItsGhosts) {
  const Vec2 v(1.0, 2.0);
  for (const FaceCondition c : {FaceCondition::fixed, FaceCondition::slip, FaceCondition::free}) {
    Grid<2> g = grid_with(c);
    for (long i = 0; i < g.node_count(); ++i) {
      g.mass[i] = 1.0;
      g.momentum[i] = v;
    }
    g.velocities_from_momentum();
    int ghosts = 0;
    for (long i = 0; i < g.node_count(); ++i) {
      const Vec2 x = g.node_position(i);
      if (x.y() < 0.0 || x.y() > 1.0 || x.x() > 1.0) continue;  // beyond the free faces
      Vec2 expected = v;
      if (std::abs(x.x()) < 1e-12) {  // on the face
        if (c == FaceCondition::fixed) expected = Vec2::Zero();
        if (c == FaceCondition::slip) expected = Vec2(0.0, v.y());
      } else if (x.x() < 0.0 && c != FaceCondition::free) {  // a ghost: its image's, mirrored
        expected = mirrored(c, g.velocity[image_of(g, i)]);
        ++ghosts;
      }
      EXPECT_EQ(g.velocity[i], expected)
          << "condition " << static_cast<int>(c) << ", node at (" << x.x() << ", " << x.y() << ")";
    }
    if (c != FaceCondition::free) {
      EXPECT_GT(ghosts, 0);
    }
  }
}

TEST(GridFaces, WhatLandsOnGhostsFoldsIntoTheirImages) {
  for (const FaceCondition c : {FaceCondition::fixed, FaceCondition::slip, FaceCondition::free}) {
    Grid<2> g = grid_with(c);
    std::vector<double> mass(g.node_count(), 1.0);
    std::vector<Vec2> momentum(g.node_count(), Vec2(1.0, 2.0));
    g.fold(mass);
    g.fold(momentum);
    int folded = 0;
    for (long i = 0; i < g.node_count(); ++i) {
      const Vec2 x = g.node_position(i);
      if (x.y() < 0.0 || x.y() > 1.0 || x.x() > 1.0) continue;  // beyond the free faces
      if (c == FaceCondition::free) {
        EXPECT_EQ(mass[i], 1.0);  // a free face folds nothing
        continue;
      }
      if (x.x() < -1e-12) {  // ghost: cleared
        EXPECT_EQ(mass[i], 0.0);
        EXPECT_EQ(momentum[i], Vec2::Zero());
      } else if (x.x() > 1e-12 && x.x() <= 2.0 * kCell + 1e-12 &&
                 g.node_position(image_of(g, i)).x() >= g.node_position(0).x()) {
        // An interior node with a ghost image: its own value plus the ghost's, reflected.
        EXPECT_EQ(mass[i], 2.0) << x.x();
        EXPECT_EQ(momentum[i], Vec2(1.0, 2.0) + mirrored(c, Vec2(1.0, 2.0))) << x.x();
        ++folded;
      }
    }
    if (c != FaceCondition::free) {
      EXPECT_GT(folded, 0);
    }
  }
}

}  // namespace
}  // namespace pellicle
