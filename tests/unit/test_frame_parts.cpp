// Frames from parts of a body (FrameEstimator::estimate_part), as the ranks of a distributed
// run estimate them (dist/halo_frames.hpp): a part holding some points and the body's points
// in the cells within the estimator's reach of theirs must give those points bitwise the
// frames of the whole body. Every registered estimator, in 2D and 3D: dense and sparse
// (joined isosurface cells) clouds, open curves and sheets ending on mirror planes (the
// planes the whole body ends on reach a part that does not touch them), closed curves.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "pellicle/normals/frame_estimator.hpp"
#include "support/membrane_bodies.hpp"

namespace pellicle {
namespace {

using test::Body;
using test::kCell;

//! The part of `ranks` slabs along x that rank r holds: its points (those in slab r of the
//! body's extent) and every point in a cell within `reach` cells of one of theirs, in order.
template <int D>
BodyPart part_of(const std::vector<Vec<D>>& x, int ranks, int r, int reach) {
  double lo = x[0].x(), hi = x[0].x();
  for (const auto& p : x) lo = std::min(lo, p.x()), hi = std::max(hi, p.x());
  auto slab = [&](const Vec<D>& p) {
    return std::min(ranks - 1, static_cast<int>((p.x() - lo) / (hi - lo) * ranks));
  };
  auto cell = [&](const Vec<D>& p) {
    return IVec<D>((p / kCell).array().floor().template cast<int>());
  };
  BodyPart part;
  part.count = static_cast<long>(x.size());
  for (long i = 0; i < part.count; ++i) {
    bool own = slab(x[i]) == r, near = own;
    for (long k = 0; k < part.count && !near; ++k)
      near = slab(x[k]) == r && (cell(x[k]) - cell(x[i])).cwiseAbs().maxCoeff() <= reach;
    if (!near) continue;
    part.index.push_back(i);
    part.wanted.push_back(own);
  }
  return part;
}

//! For every registered estimator with a reach: the whole body's frames (the first estimate
//! settles signs; the second, a step later, is the reference), then each rank's part from
//! the first frames; the wanted frames must equal the reference bitwise. Returns the names
//! of the estimators that took parts.
template <int D>
std::vector<std::string> check_parts(const Body<D>& body, int ranks, int reach_shrink = 0) {
  std::vector<std::string> took;
  const long n = static_cast<long>(body.before.size());
  for (const auto& choice : frame_estimators<D>()) {
    SCOPED_TRACE(choice.name);
    auto estimator = choice.make(body.setup);
    std::vector<Vec<D>> normal(n, Vec<D>::Zero()), tangent(n, Vec<D>::Zero());
    estimator->estimate(body.before, 0, n, normal, tangent);
    const std::vector<Vec<D>> first_normal = normal, first_tangent = tangent;
    estimator->estimate(body.after, 0, n, normal, tangent);
    const int reach = estimator->reach();
    if (reach < 0) {
      BodyPart whole;
      EXPECT_FALSE(estimator->estimate_part(whole, body.after, normal, tangent));
      continue;
    }
    unsigned planes = 0;
    std::vector<BodyPart> parts;
    for (int r = 0; r < ranks; ++r) {
      parts.push_back(part_of<D>(body.after, ranks, r, reach - reach_shrink));
      for (std::size_t j = 0; j < parts[r].index.size(); ++j)
        if (parts[r].wanted[j])
          planes |= estimator->planes_touched(body.after, parts[r].index[j], parts[r].index[j] + 1);
    }
    long compared = 0;
    bool lacking = false;  // a part without a mesh neighbour: the run gathers the body instead
    for (auto& part : parts) {
      part.planes = planes;
      std::vector<Vec<D>> x, pn, pt;
      for (long i : part.index) {
        x.push_back(body.after[i]);
        pn.push_back(first_normal[i]);
        pt.push_back(first_tangent[i]);
      }
      if (!estimator->estimate_part(part, x, pn, pt)) {
        EXPECT_EQ(choice.name, "connectivity");
        lacking = true;
        break;
      }
      for (std::size_t j = 0; j < part.index.size(); ++j) {
        if (!part.wanted[j]) continue;
        const long i = part.index[j];
        ++compared;
        for (int d = 0; d < D; ++d) {
          EXPECT_EQ(pn[j][d], normal[i][d]) << "point " << i;
          EXPECT_EQ(pt[j][d], tangent[i][d]) << "point " << i;
        }
      }
    }
    if (lacking) continue;
    EXPECT_EQ(compared, n);
    took.push_back(choice.name);
  }
  return took;
}

TEST(FrameParts, DenseQuarterArcOnMirrorPlanes) {
  const auto took = check_parts<2>(test::quarter_arc(91), 3);
  // Connectivity, the isosurface variants but the guarded, the simple and cubic colours.
  EXPECT_EQ(took.size(), 9u);
}

TEST(FrameParts, SparseClosedCircleJoinsIsosurfaceCells) {
  // 1.3 cells between points: the hybrid rule joins cells into blocks up to 4 wide.
  check_parts<2>(test::arc(Vec2(0.55, 0.45), 0.5, 0.0, 2 * std::numbers::pi, 24, true), 4);
  check_parts<2>(test::arc(Vec2(0.55, 0.45), 0.5, 0.0, 2 * std::numbers::pi, 60, true), 2);
}

TEST(FrameParts, SheetOnMirrorPlanes3D) {
  check_parts<3>(test::sheet(21, 0.05), 3);
  check_parts<3>(test::sheet(8, 0.14), 2);  // sparse: joined cells
}

}  // namespace
}  // namespace pellicle
