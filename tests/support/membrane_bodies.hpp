#pragma once
// Membrane bodies for tests of frame estimators on parts of a body (tests/unit/
// test_frame_parts.cpp, tests/mpi/test_halo_frames.cpp): their points at a first estimate
// (which settles signs) and a step later, and the estimator set-up.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "pellicle/normals/frame_estimator.hpp"

namespace pellicle::test {

inline constexpr double kCell = 0.1;

template <int D>
struct Body {
  std::vector<Vec<D>> before, after;  //!< positions at the settling estimate and a step later
  FrameSetup<D> setup;
};

//! An arc of radius r about `centre` from angle a0 to a1, n points, jittered radially.
inline Body<2> arc(Vec2 centre, double r, double a0, double a1, int n, bool closed) {
  Body<2> b;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < n; ++i) {
    const double a = a0 + (a1 - a0) * i / (closed ? n : n - 1);
    const double radius = r * (1.0 + 0.01 * u(rng));
    b.before.push_back(centre + radius * Vec2(std::cos(a), std::sin(a)));
    // A step later: stretched unevenly and shifted, by a fraction of a cell.
    b.after.push_back(centre + (radius + 0.02 * std::sin(3 * a)) * Vec2(std::cos(a), std::sin(a)) +
                      Vec2(0.003, -0.002) * u(rng));
  }
  b.setup.connectivity.closed_curve = closed;
  b.setup.cell = kCell;
  return b;
}

//! The quarter arc of radius 0.5 about the origin, its ends on the planes x = 0 and y = 0.
inline Body<2> quarter_arc(int n) {
  Body<2> b = arc(Vec2::Zero(), 0.5, 0.0, std::numbers::pi / 2, n, false);
  for (auto* x : {&b.before, &b.after}) {
    x->front().y() = 0.0;
    x->back().x() = 0.0;
  }
  b.setup.mirrors = {{0, 0.0}, {1, 0.0}, {0, 1.0}};
  return b;
}

//! A wavy sheet over [0, L]² (m × m points, L = (m − 1) spacing) meshed in triangles, its
//! edges x = 0 and y = 0 on mirror planes.
inline Body<3> sheet(int m, double spacing) {
  Body<3> b;
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const double x = i * spacing, y = j * spacing;
      const Vec3 p(x, y, 0.5 + 0.1 * std::cos(2 * x) * std::cos(3 * y) + 0.002 * u(rng));
      b.before.push_back(p);
      Vec3 q = p + Vec3(0.01 * std::sin(4 * y), 0.01 * std::sin(5 * x), 0.02 * x * y);
      if (i == 0) q.x() = 0.0;
      if (j == 0) q.y() = 0.0;
      b.after.push_back(q);
    }
  for (int j = 0; j + 1 < m; ++j)
    for (int i = 0; i + 1 < m; ++i) {
      const int a = j * m + i;
      b.setup.connectivity.triangles.push_back({a, a + 1, a + m + 1});
      b.setup.connectivity.triangles.push_back({a, a + m + 1, a + m});
    }
  b.setup.cell = kCell;
  b.setup.mirrors = {{0, 0.0}, {1, 0.0}};
  b.setup.orientation.rule = NormalOrientation::propagate;
  return b;
}

}  // namespace pellicle::test
