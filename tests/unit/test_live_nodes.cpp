// Live nodes (docs/theory/performance.md, "Live nodes"): the grid passes visit per row only
// the span of nodes a step may write. Checked here: a restart clears what the last step wrote
// and keeps nothing else, the live set is closed under the ghost mirrors of constrained faces
// (so folding and mirroring stay inside it), marked nodes join it, the momentum update
// over the live nodes gives every node of the grid what the update over all nodes gives, and
// each body's own field (contact) holds only the nodes of its own points' stencils.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <random>
#include <vector>

#include "pellicle/mpm/grid.hpp"
#include "pellicle/mpm/particles.hpp"
#include "pellicle/mpm/transfer.hpp"

namespace pellicle {
namespace {

template <int D>
Grid<D> walled_grid(double cell) {
  FaceConditions<D> faces;
  faces.fill(FaceCondition::fixed);
  faces[1] = FaceCondition::slip;  // x-max
  faces[2] = FaceCondition::free;  // y-min
  return Grid<D>(Vec<D>::Zero(), Vec<D>::Ones(), cell, faces);
}

//! True when `spans` (one per row of g's storage) hold `node`.
template <int D>
bool holds(const Grid<D>& g, const std::vector<NodeSpan>& spans, long node) {
  const NodeSpan& s = spans[node / g.nodes()[0]];
  const int x = static_cast<int>(node % g.nodes()[0]);
  return x >= s.first && x <= s.last;
}

//! Spans a few scattered 3-wide stencils reach, some of them into the ghost layers.
template <int D>
std::vector<NodeSpan> some_spans(const Grid<D>& g, std::mt19937& rng) {
  std::vector<NodeSpan> spans(g.row_count());
  std::uniform_int_distribution<int> pick(0, 1 << 20);
  for (int k = 0; k < 6; ++k) {
    int first[D];
    for (int d = 0; d < D; ++d) first[d] = pick(rng) % (g.nodes()[d] - 2);
    first[0] = k == 0 ? 0 : first[0];  // one reaches the x-min ghosts
    const long row = g.row_of(first);
    for (int c = 0; c < (D == 3 ? 3 : 1); ++c)
      for (int b = 0; b < 3; ++b)
        spans[row + b + c * (D == 3 ? g.nodes()[1] : 0)].add(first[0], first[0] + 2);
  }
  return spans;
}

template <int D>
void fill_live(Grid<D>& g, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.5, 1.5);
  for (long n = 0; n < g.node_count(); ++n) {
    if (!g.is_live(n)) continue;
    g.mass[n] = u(rng);
    for (int d = 0; d < D; ++d) {
      g.momentum[n][d] = u(rng);
      g.force[n][d] = u(rng);
      g.velocity[n][d] = u(rng);
      g.velocity_change[n][d] = u(rng);
    }
  }
}

template <int D>
void expect_restart_clears_the_last_step() {
  std::mt19937 rng(7);
  Grid<D> g = walled_grid<D>(1.0 / 32);
  fill_live(g, rng);  // a new grid is live everywhere
  const std::vector<Vec<D>> velocity = g.velocity;
  const std::vector<NodeSpan> next = some_spans(g, rng);
  g.restart_live(next);
  long live = 0;
  for (long n = 0; n < g.node_count(); ++n) {
    ASSERT_EQ(g.mass[n], 0.0);
    ASSERT_TRUE(g.momentum[n].isZero(0.0) && g.force[n].isZero(0.0));
    live += g.is_live(n);
    if (holds(g, next, n)) {  // kept: the update rewrites them
      ASSERT_EQ(g.velocity[n], velocity[n]) << "node " << n;
    } else if (!g.is_live(n)) {
      ASSERT_TRUE(g.velocity[n].isZero(0.0) && g.velocity_change[n].isZero(0.0)) << "node " << n;
    }
  }
  EXPECT_GT(live, 0);
  EXPECT_LT(live, g.node_count() / 2);
}

TEST(LiveNodes, RestartClearsTheLastStepsNodes2D) {
  expect_restart_clears_the_last_step<2>();
}
TEST(LiveNodes, RestartClearsTheLastStepsNodes3D) {
  expect_restart_clears_the_last_step<3>();
}

//! Every live node's mirror image across a constrained face, within the ghost layers, is live.
template <int D>
void expect_closed_under_mirrors() {
  std::mt19937 rng(11);
  Grid<D> g = walled_grid<D>(0.125);
  g.restart_live(some_spans(g, rng));
  int pairs = 0;
  for (long n = 0; n < g.node_count(); ++n) {
    if (!g.is_live(n)) continue;
    for (int d = 0; d < D; ++d)
      for (int side = 0; side < 2; ++side) {
        if (g.faces()[2 * d + side] == FaceCondition::free) continue;
        const int face = side == 0 ? Grid<D>::kGhost : Grid<D>::kGhost + g.cells()[d];
        IVec<D> index = g.unflatten(n);
        const int k = index[d] - face;
        if (k == 0 || std::abs(k) > Grid<D>::kGhost) continue;
        index[d] = face - k;
        ++pairs;
        EXPECT_TRUE(g.is_live(g.flatten(index))) << "node " << n << " axis " << d;
      }
  }
  EXPECT_GT(pairs, 0);
}

TEST(LiveNodes, ClosedUnderTheGhostMirrors2D) {
  expect_closed_under_mirrors<2>();
}
TEST(LiveNodes, ClosedUnderTheGhostMirrors3D) {
  expect_closed_under_mirrors<3>();
}

TEST(LiveNodes, MarkedAndPrescribedNodesJoin) {
  Grid<2> g = walled_grid<2>(0.125);
  g.restart_live(std::vector<NodeSpan>(g.row_count()));
  for (long n = 0; n < g.node_count(); ++n) ASSERT_FALSE(g.is_live(n));
  const long marked = g.flatten(IVec<2>(5, 6)), prescribed = g.flatten(IVec<2>(7, 3));
  g.mark_live(&marked, &marked + 1);
  g.prescribe({{prescribed, Vec2(1.0, 0.0)}});
  EXPECT_TRUE(g.is_live(marked));
  EXPECT_TRUE(g.is_live(prescribed));
  g.integrate(0.1);
  EXPECT_EQ(g.velocity[prescribed], Vec2(1.0, 0.0));
}

//! The update over the live nodes equals the update over every node, node by node.
template <int D>
void expect_update_as_over_every_node(int threads) {
  std::mt19937 rng(3);
  Grid<D> live = walled_grid<D>(0.1);
  live.restart_live(some_spans(live, rng));
  fill_live(live, rng);
  Grid<D> whole = walled_grid<D>(0.1);  // live everywhere
  whole.mass = live.mass, whole.momentum = live.momentum, whole.force = live.force;
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  live.fold(live.mass), live.fold(live.momentum), live.fold(live.force);
  whole.fold(whole.mass), whole.fold(whole.momentum), whole.fold(whole.force);
  live.integrate(0.01);
  whole.integrate(0.01);
  omp_set_num_threads(before);
  for (long n = 0; n < live.node_count(); ++n) {
    ASSERT_EQ(live.velocity[n], whole.velocity[n]) << "node " << n;
    ASSERT_EQ(live.velocity_change[n], whole.velocity_change[n]) << "node " << n;
  }
}

TEST(LiveNodes, UpdateAsOverEveryNode) {
  for (int threads : {1, 2, 3}) {
    expect_update_as_over_every_node<2>(threads);
    expect_update_as_over_every_node<3>(threads);
  }
}

//! After compute_stencils and to_grid every node a point's stencil weighs is live, and every
//! node with mass is one of them: points in runs along rows (as a fill places them), in
//! random order, and a few in the ghost-adjacent cells of walled faces.
template <int D>
void expect_stencils_live(int threads) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  for (const auto& kernel : kernel_choices<D>()) {
    Grid<D> grid = walled_grid<D>(1.0 / 16);
    Particles<D> points;
    TransferOptions options;
    options.kinematics = D == 2 ? Kinematics::plane_strain : Kinematics::solid;
    auto transfer = kernel.make(options, 2.0);
    transfer->declare_columns(points);
    points.bodies.push_back({"cloud", 0, Vec<D>::Zero(), 0, 0, nullptr});
    for (int k = 0; k < 200; ++k) {  // a run along axis 0, then scattered points
      Vec<D> x;
      for (int d = 0; d < D; ++d) x[d] = k < 40 ? (d == 0 ? 0.3 + 0.01 * k : 0.4) : u(rng);
      points.add(x, Vec<D>::Zero(), 1.0, 1.0);
    }
    transfer->compute_stencils(points, grid, {});
    transfer->to_grid(points, Vec<D>::Zero(), grid, false);
    std::vector<long> reached;
    transfer->touched_nodes(grid, 0, points.size(), reached);
    for (long n : reached) ASSERT_TRUE(grid.is_live(n)) << kernel.name << " node " << n;
    long live = 0;
    for (long n = 0; n < grid.node_count(); ++n) {
      live += grid.is_live(n);
      ASSERT_TRUE(grid.mass[n] == 0.0 || grid.is_live(n)) << kernel.name << " node " << n;
    }
    EXPECT_LT(live, grid.node_count()) << kernel.name;
  }
  omp_set_num_threads(before);
}

TEST(LiveNodes, StencilsOfEveryKernelAreLive) {
  for (int threads : {1, 2}) {
    expect_stencils_live<2>(threads);
    expect_stencils_live<3>(threads);
  }
}

//! Two bodies, each scattered into its own field over its point range (contact models' fields
//! per body): each field's live nodes are those of its own points' stencils, not the other
//! body's, and with 2 or 3 threads (the threads' node shares found while anchoring) the fields
//! hold what one thread gives. Points in random order, so the threads' shares overlap.
template <int D>
void expect_body_fields_own_nodes(int threads) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto& kernel = kernel_choices<D>()[0];
  Particles<D> points;
  for (int b = 0; b < 2; ++b) {
    points.bodies.push_back(
        {b == 0 ? "left" : "right", 0, Vec<D>::Zero(), points.size(), 0, nullptr});
    for (int k = 0; k < 300; ++k) {
      Vec<D> x, v;
      for (int d = 0; d < D; ++d) x[d] = 0.1 + 0.3 * u(rng), v[d] = u(rng) - 0.5;
      x[0] += 0.5 * b;  // left: x < 0.4; right: x > 0.6
      points.add(x, v, 1.0 + u(rng), 1.0);
    }
    points.bodies.back().end = points.size();
  }
  const std::vector<PointRange> ranges = {{0, 300}, {300, 600}};
  const Vec<D> gravity = Vec<D>::Constant(-1.0);
  // Scatters each body into its own field with `threads` threads; `told` whether
  // compute_stencils hears of the ranges.
  auto scatter = [&](int team, bool told) {
    TransferOptions options;
    options.kinematics = D == 2 ? Kinematics::plane_strain : Kinematics::solid;
    auto transfer = kernel.make(options, 2.0);
    transfer->declare_columns(points);
    std::vector<Grid<D>> fields(2, walled_grid<D>(1.0 / 16));
    const int before = omp_get_max_threads();
    omp_set_num_threads(team);
    transfer->compute_stencils(points, fields[0], told ? ranges : std::vector<PointRange>{});
    for (int b = 0; b < 2; ++b) transfer->to_grid(points, gravity, fields[b], true, ranges[b]);
    omp_set_num_threads(before);
    return std::pair(std::move(transfer), std::move(fields));
  };
  const auto [one, one_thread] = scatter(1, true);
  const auto [transfer, fields] = scatter(threads, true);
  const auto [untold_transfer, untold] = scatter(threads, false);
  for (int b = 0; b < 2; ++b) {
    std::vector<long> own, other;
    transfer->touched_nodes(fields[b], ranges[b].begin, ranges[b].end, own);
    transfer->touched_nodes(fields[b], ranges[1 - b].begin, ranges[1 - b].end, other);
    for (long n : own) ASSERT_TRUE(fields[b].is_live(n)) << "body " << b << " node " << n;
    for (long n : other) ASSERT_FALSE(fields[b].is_live(n)) << "body " << b << " node " << n;
    // Not told of the ranges: every field takes the nodes of all points, and the same sums.
    for (long n : other) ASSERT_TRUE(untold[b].is_live(n)) << "body " << b << " node " << n;
    for (long n = 0; n < fields[b].node_count(); ++n) {
      const double m = one_thread[b].mass[n], tolerance = 1e-13 * (1.0 + m);
      ASSERT_NEAR(fields[b].mass[n], m, tolerance) << "body " << b << " node " << n;
      ASSERT_NEAR(untold[b].mass[n], m, tolerance) << "body " << b << " node " << n;
      for (int d = 0; d < D; ++d) {
        ASSERT_NEAR(fields[b].momentum[n][d], one_thread[b].momentum[n][d], tolerance);
        ASSERT_NEAR(fields[b].force[n][d], one_thread[b].force[n][d], tolerance);
        ASSERT_NEAR(untold[b].force[n][d], one_thread[b].force[n][d], tolerance);
      }
    }
  }
}

TEST(LiveNodes, EachBodysFieldHoldsItsOwnNodes) {
  for (int threads : {1, 2, 3}) {
    expect_body_fields_own_nodes<2>(threads);
    expect_body_fields_own_nodes<3>(threads);
  }
}

}  // namespace
}  // namespace pellicle
