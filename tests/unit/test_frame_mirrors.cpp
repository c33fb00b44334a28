// Connectivity-free frames at the ends of a quarter model: the membrane ends on symmetry
// planes (docs/theory/normals.md, "Ends on symmetry planes and walls"), so the end normals
// must lie in those planes, as the connectivity estimator's mirrored neighbour makes them;
// and the mirror images the estimators add come only from planes the membrane ends on.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "pellicle/normals/frame_estimator.hpp"
#include "pellicle/normals/mirror_images.hpp"

namespace pellicle {
namespace {

// A quarter arc of radius r from (r, 0) to (0, r), 91 points, its interior points jittered
// radially by up to `jitter` (a membrane's small-scale noise); cell 0.1 as Sulsky & York's
// §8 ex. 1. The ends lie on the planes.
std::vector<Vec2> quarter_arc(double r, double jitter) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec2> x;
  for (int i = 0; i < 91; ++i) {
    const double a = std::numbers::pi / 2 * i / 90;
    const double radius = r + (i == 0 || i == 90 ? 0.0 : jitter * u(rng));
    x.emplace_back(radius * std::cos(a), radius * std::sin(a));
  }
  x.front().y() = 0.0;
  x.back().x() = 0.0;
  return x;
}

TEST(FrameMirrors, ImagesComeFromThePlanesTheMembraneEndsOn) {
  const auto x = quarter_arc(0.5, 0.0);
  // x = 0 and y = 0 hold the ends; x = 1 (a wall the arc does not reach) gives no images.
  const std::vector<MirrorPlane> planes{{0, 0.0}, {1, 0.0}, {0, 1.0}};
  const auto ends_on = planes_ended_on<2>(x, 0, 91, planes, 0.1);
  ASSERT_EQ(ends_on.size(), 2u);
  const auto cloud = with_mirror_images<2>(x, 0, 91, planes, 0.1, 0.2);
  long near_x = 0, near_y = 0;  // points within 0.2 of a plane, not on it
  for (const auto& p : x) {
    near_x += p.x() > 1e-12 && p.x() <= 0.2;
    near_y += p.y() > 1e-12 && p.y() <= 0.2;
  }
  ASSERT_EQ(static_cast<long>(cloud.size()), 91 + near_x + near_y);  // no corner points here
  for (std::size_t k = 91; k < cloud.size(); ++k) {
    EXPECT_TRUE(cloud[k].x() < 0.0 || cloud[k].y() < 0.0) << k;
    EXPECT_NEAR(cloud[k].norm(), 0.5, 1e-12) << k;  // on the mirrored arc
  }
}

TEST(FrameMirrors, EndNormalsLieInTheSymmetryPlanes) {
  FrameSetup<2> setup;
  setup.cell = 0.1;
  setup.mirrors = {{0, 0.0}, {1, 0.0}};
  // Radii off the cell lines (the first step's stretch) and on one; with and without jitter.
  // Without the images the end normals tilted by 1.5–6° (pca, hybrid) and up to 66°
  // (quadratic) in these configurations.
  for (double r : {0.5021, 0.5047}) {
    for (double jitter : {0.0, 2e-4, 5e-4}) {
      const auto x = quarter_arc(r, jitter);
      for (const char* name : {"isosurface-hybrid", "isosurface-quadratic", "pca"}) {
        std::unique_ptr<FrameEstimator<2>> estimator;
        for (const auto& e : frame_estimators<2>())
          if (e.name == name) estimator = e.make(setup);
        ASSERT_TRUE(estimator);
        std::vector<Vec2> n(91, Vec2::Zero()), t(91, Vec2::Zero());
        estimator->estimate(x, 0, 91, n, t);
        // On y = 0 the normal is ±x; on x = 0 it is ±y.
        EXPECT_LT(std::abs(n.front().y()), std::sin(0.5 * std::numbers::pi / 180))
            << name << " r " << r << " jitter " << jitter;
        EXPECT_LT(std::abs(n.back().x()), std::sin(0.5 * std::numbers::pi / 180))
            << name << " r " << r << " jitter " << jitter;
      }
    }
  }
}

}  // namespace
}  // namespace pellicle
