// Membrane frames on the ranks of a distributed run (dist/halo_frames.hpp): each rank holds
// a slab of a body's points, in an order of its own (as migration leaves them). The first
// estimate gathers the whole body; later ones take each rank's part and the halo its
// estimator reaches, except for estimators whose frames depend on the whole body. Either
// way every rank's frames must be bitwise those of the whole body in one process.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "pellicle/dist/halo_frames.hpp"
#include "support/membrane_bodies.hpp"
#include "world.hpp"

namespace pellicle {
namespace {

//! This rank's points of the body: those in its slab along x (of the first positions), or
//! (`interleaved`) every size-th point from its rank's, in reverse order of their index.
template <int D>
std::vector<long> own_points(const std::vector<Vec<D>>& x, bool interleaved) {
  double lo = x[0].x(), hi = x[0].x();
  for (const auto& p : x) lo = std::min(lo, p.x()), hi = std::max(hi, p.x());
  const int ranks = world->size();
  auto owner = [&](long i) {
    return interleaved ? static_cast<int>(i % ranks)
                       : std::min(ranks - 1, static_cast<int>((x[i].x() - lo) / (hi - lo) * ranks));
  };
  std::vector<long> mine;
  for (long i = static_cast<long>(x.size()) - 1; i >= 0; --i)
    if (owner(i) == world->rank()) mine.push_back(i);
  return mine;
}

//! Two estimates, settling and a step later, of each named estimator on the whole body and
//! split over the ranks; the split frames must be the whole ones. `halo`: whether the
//! second estimate should come from a halo; `interleaved`: how the points are split.
template <int D>
void expect_whole_body_frames(const test::Body<D>& body, const std::string& name, bool halo,
                              bool interleaved = false) {
  SCOPED_TRACE(name);
  const FrameEstimatorChoice<D>* choice = nullptr;
  for (const auto& c : frame_estimators<D>())
    if (c.name == name) choice = &c;
  ASSERT_NE(choice, nullptr);
  const long n = static_cast<long>(body.before.size());
  std::vector<Vec<D>> whole_normal(n, Vec<D>::Zero()), whole_tangent(n, Vec<D>::Zero());
  auto whole = choice->make(body.setup);
  whole->estimate(body.before, 0, n, whole_normal, whole_tangent);
  whole->estimate(body.after, 0, n, whole_normal, whole_tangent);

  const std::vector<long> mine = own_points<D>(body.before, interleaved);
  Particles<D> points;
  points.bodies.push_back({});
  for (long i : mine) points.add(body.before[i], Vec<D>::Zero(), 1.0, 1.0);
  const auto index = points.template declare<double>({column_names::body_index, "1", true, false});
  for (std::size_t k = 0; k < mine.size(); ++k) points[index][k] = static_cast<double>(mine[k]);
  const long own = points.size();
  HaloFrames<D> frames(*world, choice->make(body.setup), points, index, n, test::kCell);
  std::vector<Vec<D>> normal(own, Vec<D>::Zero()), tangent(own, Vec<D>::Zero());
  frames.estimate(points.position, 0, own, normal, tangent);
  for (std::size_t k = 0; k < mine.size(); ++k) points.position[k] = body.after[mine[k]];
  frames.estimate(points.position, 0, own, normal, tangent);

  EXPECT_EQ(frames.gathered_estimates(), halo ? 1 : 2);
  EXPECT_EQ(frames.halo_estimates(), halo ? 1 : 0);
  for (std::size_t k = 0; k < mine.size(); ++k)
    for (int d = 0; d < D; ++d) {
      EXPECT_EQ(normal[k][d], whole_normal[mine[k]][d]) << "point " << mine[k];
      EXPECT_EQ(tangent[k][d], whole_tangent[mine[k]][d]) << "point " << mine[k];
    }
}

TEST(HaloFrames, QuarterArcOnMirrorPlanesGetsTheWholeBodysFrames) {
  const auto arc = test::quarter_arc(91);
  for (const char* name : {"connectivity", "isosurface-hybrid", "isosurface-quadratic",
                           "colour-simple", "colour-cubic"}) {
    expect_whole_body_frames<2>(arc, name, true);
    // Ranks whose points come near a plane without one on it: the planes the whole body
    // ends on still mirror them.
    expect_whole_body_frames<2>(arc, name, true, true);
  }
  // Frames that depend on the whole body: gathered every time.
  for (const char* name : {"pca", "isosurface-guarded", "colour-quadratic"})
    expect_whole_body_frames<2>(arc, name, false);
}

TEST(HaloFrames, SparseClosedCircleGetsTheWholeBodysFrames) {
  // 1.3 cells between points: joined isosurface cells reach 3 cells.
  const auto circle = test::arc(Vec2(0.55, 0.45), 0.5, 0.0, 6.283185307179586, 24, true);
  expect_whole_body_frames<2>(circle, "isosurface-hybrid", true);
}

TEST(HaloFrames, SheetGetsTheWholeBodysFrames3D) {
  const auto sheet = test::sheet(21, 0.05);
  for (const char* name : {"connectivity", "isosurface-hybrid"})
    expect_whole_body_frames<3>(sheet, name, true);
}

}  // namespace
}  // namespace pellicle
