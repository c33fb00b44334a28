// Distributed runs agree with one process (DESIGN.md: np = 1, 2, 3 give the same results to
// round-off). Every rank builds the case twice: whole, run as one process would, and split
// over the ranks as `pellicle run` splits it (dist/distributed_run.hpp): each rank builds only
// the points of its patch. After every step the split run's whole-system
// state, reduced over the ranks, must equal the whole run's to 1e-12 of its scale. ctest runs
// this under mpirun with 1, 2 and 3 ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "pellicle/core/error.hpp"
#include "pellicle/dist/distributed_run.hpp"
#include "pellicle/dist/halo_frames.hpp"
#include "pellicle/validation/support.hpp"
#include "world.hpp"

namespace pellicle {
namespace {

constexpr double kTolerance = 1e-12;

//! Σ m |v| of every point: the scale momentum errors are measured on.
template <int D>
double momentum_scale(const Simulation<D>& s) {
  double sum = 0.0;
  for (long p = 0; p < s.point_count(); ++p)
    sum += s.points().mass[p] * s.points().velocity[p].norm();
  return sum;
}

//! Largest differences between the split and the whole run, relative to their scales.
struct Agreement {
  double time = 0.0, energy = 0.0, momentum = 0.0, centre = 0.0;
  double contact = 0.0;   //!< contact forces on the bodies, where a contact model acts
  double material = 0.0;  //!< the materials' history sums (pressure, volume, …) per body
  double enclosed = 0.0;  //!< volumes bodies inside membranes fill, and their membranes' tension
  long steps = 0;
  std::vector<std::pair<std::string, double>> figures;  //!< the split run's summary figures
  //! The split run's membrane frame estimates from halos and from whole bodies gathered.
  long halo_frames = 0, gathered_frames = 0;
};

//! Run the case to its end time whole and split (at most `max_steps`: a broken split run
//! may take ever smaller steps); the largest differences on the way.
template <int D>
Agreement compare_runs(const std::string& file, const std::vector<std::string>& overrides,
                       long max_steps) {
  auto whole = validation::builtin_simulation<D>(file, overrides);
  std::vector<Patch<D>> split_patches;
  auto split = validation::builtin_simulation<D>(file, overrides,
                                                 patch_points<D>(*world, {}, split_patches));
  std::vector<long> points = {split->point_count()};
  world->sum(points);
  EXPECT_EQ(points[0], whole->point_count()) << "every point is built on exactly one rank";
  if (world->size() > 1) {
    EXPECT_LT(split->point_count(), whole->point_count());
  }
  const PatchRun<D>& patches = distribute(*split, *world, std::move(split_patches));

  Agreement a;
  double energy_scale = 0.0, momentum_scale_max = 0.0, force_scale = 0.0;
  std::vector<double> material_scale;
  const double length = (whole->grid().upper() - whole->grid().lower()).norm();
  while (!whole->finished() && a.steps < max_steps) {
    whole->step();
    split->step();
    ++a.steps;
    const SystemState<D> w = whole->state(), s = split->state();
    energy_scale = std::max(energy_scale, std::abs(w.kinetic) + std::abs(w.strain) +
                                              std::abs(w.internal) + std::abs(w.gravitational));
    momentum_scale_max = std::max(momentum_scale_max, momentum_scale(*whole));
    a.time = std::max(a.time, std::abs(split->time() - whole->time()) / whole->time());
    for (double diff : {s.kinetic - w.kinetic, s.strain - w.strain, s.internal - w.internal,
                        s.gravitational - w.gravitational})
      a.energy = std::max(a.energy, std::abs(diff) / energy_scale);
    a.momentum = std::max(a.momentum,
                          (s.momentum - w.momentum).norm() / std::max(momentum_scale_max, 1e-300));
    // Contact forces: each rank's over the nodes it owns, summed.
    if (const auto* forces = whole->contact_forces()) {
      std::vector<double> sums;
      for (const auto& f : *split->contact_forces())
        sums.insert(sums.end(), f.data(), f.data() + D);
      world->sum_in_rank_order(sums);
      double total = 0.0;
      for (const auto& f : *forces) total += f.norm();
      force_scale = std::max(force_scale, total);
      for (std::size_t b = 0; b < forces->size(); ++b)
        a.contact = std::max(a.contact, (Vec<D>(sums.data() + b * D) - (*forces)[b]).norm() /
                                            std::max(force_scale, 1e-300));
    }
    // The materials' history sums of each body, each against its largest value so far.
    std::vector<double> whole_sums, split_sums;
    for (const auto& b : whole->points().bodies)
      whole->material(b.material).history_sums(whole->points(), b.begin, b.end, whole_sums);
    for (const auto& b : split->points().bodies)
      split->material(b.material).history_sums(split->points(), b.begin, b.end, split_sums);
    world->sum_in_rank_order(split_sums);
    material_scale.resize(whole_sums.size(), 0.0);
    for (std::size_t i = 0; i < whole_sums.size(); ++i) {
      material_scale[i] = std::max(material_scale[i], std::abs(whole_sums[i]));
      if (material_scale[i] > 0.0)
        a.material =
            std::max(a.material, std::abs(split_sums[i] - whole_sums[i]) / material_scale[i]);
    }
    // What bodies inside membranes are measured by (history.csv), relative to the value.
    for (std::size_t k = 0; k < whole->enclosed().size(); ++k) {
      const auto kinematics = whole->settings().kinematics;
      const double volume = enclosed_volume(whole->points(), whole->enclosed()[k], kinematics);
      const double tension = mean_tension(whole->points(), whole->enclosed()[k]);
      a.enclosed = std::max(
          {a.enclosed,
           std::abs(enclosed_volume(split->points(), split->enclosed()[k], kinematics, world) -
                    volume) /
               volume,
           std::abs(mean_tension(split->points(), split->enclosed()[k], world) - tension) /
               std::max(std::abs(tension), 1e-300)});
      EXPECT_EQ(escaped_points(split->points(), split->enclosed()[k], world),
                escaped_points(whole->points(), whole->enclosed()[k]));
    }
    // Each body's centre of mass, from the split run's ranks' sums.
    const auto& bodies = whole->points().bodies;
    std::vector<double> sums;
    for (const auto& b : split->points().bodies) {
      double m = 0.0;
      Vec<D> mx = Vec<D>::Zero();
      for (long p = b.begin; p < b.end; ++p) {
        m += split->points().mass[p];
        mx += split->points().mass[p] * split->points().position[p];
      }
      sums.push_back(m);
      sums.insert(sums.end(), mx.data(), mx.data() + D);
    }
    world->sum_in_rank_order(sums);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      double m = 0.0;
      Vec<D> mx = Vec<D>::Zero();
      for (long p = bodies[b].begin; p < bodies[b].end; ++p) {
        m += whole->points().mass[p];
        mx += whole->points().mass[p] * whole->points().position[p];
      }
      const Vec<D> split_centre = Vec<D>(sums.data() + b * (D + 1) + 1) / sums[b * (D + 1)];
      a.centre = std::max(a.centre, (split_centre - mx / m).norm() / length);
    }
  }
  EXPECT_TRUE(whole->finished());
  EXPECT_TRUE(split->finished());
  patches.summary_figures(a.figures);
  for (const auto& b : split->points().bodies)
    if (const auto* frames = dynamic_cast<const HaloFrames<D>*>(b.frames.get())) {
      a.halo_frames += frames->halo_estimates();
      a.gathered_frames += frames->gathered_estimates();
    }
  if (world->rank() == 0)
    std::printf(
        "%ld steps on %d ranks: largest differences, relative: time %.2g, energy %.2g, "
        "momentum %.2g, centres %.2g, contact forces %.2g, material sums %.2g, enclosed %.2g\n",
        a.steps, world->size(), a.time, a.energy, a.momentum, a.centre, a.contact, a.material,
        a.enclosed);
  return a;
}

void expect_agreement(const Agreement& a) {
  EXPECT_LE(a.time, kTolerance);
  EXPECT_LE(a.energy, kTolerance);
  EXPECT_LE(a.momentum, kTolerance);
  EXPECT_LE(a.centre, kTolerance);
  EXPECT_LE(a.contact, kTolerance);
  EXPECT_LE(a.material, kTolerance);
  EXPECT_LE(a.enclosed, kTolerance);
}

//! The membrane's frames came from halos at every step but the settling first estimate.
void expect_halo_frames(const Agreement& a) {
  EXPECT_EQ(a.gathered_frames, 1);
  EXPECT_EQ(a.halo_frames, a.steps);
}

//! On more than one rank, the run split its patches anew at least once.
void expect_rebalanced(const Agreement& a) {
  double rebalances = -1.0;
  for (const auto& [name, value] : a.figures)
    if (name == "distributed.rebalances") rebalances = value;
  if (world->size() > 1) {
    EXPECT_GT(rebalances, 0.0);
  }
}

TEST(DistributedRun, TwoDisksThroughTheirCollisionAgreeWithOneProcess) {
  // The disks touch near t = 1.6 s; a cell twice the case's keeps the run short.
  const Agreement a =
      compare_runs<2>("two_disks.toml", {"grid.cell=0.025", "solver.end_time=2.2"}, 400);
  expect_agreement(a);
}

TEST(DistributedRun, TwoDisksWithLinearFlipAndUslAgreeWithOneProcess) {
  const Agreement a = compare_runs<2>(
      "two_disks.toml",
      {"grid.cell=0.025", "solver.kernel=\"linear\"", "solver.velocity_update=\"flip\"",
       "solver.scheme=\"usl\"", "solver.end_time=2.2"},
      400);
  expect_agreement(a);
}

TEST(DistributedRun, SodSplitAnewAsTheGasMovesAgreesWithOneProcess) {
  // The gas flows across the cuts; a rebalance limit of 0.1 % splits the patches again as
  // soon as a few points have moved: new windows, new shared nodes, points sent across.
  const Agreement a = compare_runs<2>("sod_shock_tube.toml", {"solver.rebalance=0.001"}, 1500);
  expect_agreement(a);
  expect_rebalanced(a);
}

TEST(DistributedRun, SodShockTubeAgreesWithOneProcess) {
  // Gas with artificial viscosity, walls at both ends, points crossing between patches.
  const Agreement a = compare_runs<2>("sod_shock_tube.toml", {}, 1500);
  expect_agreement(a);
}

TEST(DistributedRun, SodWithCellDensitiesAgreesWithOneProcess) {
  // Point densities from the mass spread to cell centres: cell sums across the cut.
  const Agreement a = compare_runs<2>("sod_shock_tube.toml",
                                      {"material[0].density_update=\"cell-quadratic\""}, 1500);
  expect_agreement(a);
}

TEST(DistributedRun, TwoDisksWithContactReleaseAgreeWithOneProcess) {
  // The disks meet on the cut between the patches: the contact decision at nodes both ranks
  // hold reads colour functions summed over the cells they share.
  const Agreement a = compare_runs<2>(
      "two_disks.toml",
      {"grid.cell=0.025", "solver.end_time=2.2", "contact={model=\"release\", criterion=\"both\"}"},
      400);
  expect_agreement(a);
}

TEST(DistributedRun, TwoBarsWithReleaseSplitAnewAgreeWithOneProcess) {
  // Rebalancing moves the windows: the release state of each node (kept from step to step)
  // goes to the new windows from the ranks that owned the nodes.
  const Agreement a =
      compare_runs<2>("two_bars_stick.toml",
                      {"grid.cell=0.125", "solver.dt=1e-4", "solver.rebalance=0.001",
                       "contact={model=\"release\", criterion=\"both\"}"},
                      6000);
  expect_agreement(a);
  expect_rebalanced(a);
}

TEST(DistributedRun, PlatePulledByARigidGripAgreesWithOneProcess) {
  // A grip as heavy in points as the plate: the cut falls where they meet, so the nodes
  // between them are touched by the grip's points on one rank and the plate's on the other,
  // and both ranks must prescribe them.
  const Agreement a =
      compare_runs<2>("j2_plate.toml",
                      {"grid.upper=[2.25, 0.2]",
                       "body[1].region={shape=\"box\", lower=[1.0, 0.0], upper=[2.0, 0.2]}"},
                      5000);
  expect_agreement(a);
}

TEST(DistributedRun, BlockSlidingOnARigidPlateAgreesWithOneProcess) {
  // Coulomb friction against a rigid plate that spans every patch.
  const Agreement a = compare_runs<2>("friction_block.toml", {}, 3000);
  expect_agreement(a);
}

TEST(DistributedRun, PendulumAgreesWithOneProcess) {
  // A membrane string held at the top row of nodes swings across the patches' cut (0.5 s,
  // past the bottom of its swing, 16,800 steps): its connectivity frames take neighbours in
  // generation order, which migration reorders. Round-off differences grow along the swing
  // as they do between one and two threads of one process (momentum 1.2e-12 of its largest
  // value apart by 0.6 s), so the run stops at 0.5 s.
  const Agreement a =
      compare_runs<2>("pendulum.toml",
                      {"grid.cell=0.05", "solver.end_time=0.5",
                       "body[0].membrane={shape=\"polyline\", vertices=[[0.5, 0.9999], "
                       "[0.252721318, 0.313057039]], points=80, thickness=0.01}",
                       "body[0].point_masses=[[79, 3.3]]"},
                      25000);
  expect_agreement(a);
  expect_halo_frames(a);
}

TEST(DistributedRun, GasInAQuarterCircleMembraneAgreesWithOneProcess) {
  // Fluid–membrane interaction: gas pressing on a membrane that encloses it (thesis §6.2),
  // the enclosed volume and tension measured from the membrane gathered in its order.
  const Agreement a = compare_runs<2>("fsi_quarter_circle.toml", {}, 2000);
  expect_agreement(a);
  expect_halo_frames(a);
}

TEST(DistributedRun, AStepTooLongStopsEveryRankAndOnlyRanksWithTheFastestPointNameOne) {
  // One small block in a 10 × 10 grid: on three ranks the lowest patch holds no points. The
  // CFL check fails on every rank after the speeds' reduction; a rank without points must
  // name no point (it once read point 0 of nothing and crashed).
  const std::vector<std::string> overrides = {
      "grid.cell=0.1", "solver.cfl=0.9", "solver.cfl_limit=0.1",
      "body=[{name=\"block\", material=\"elastic\", points_per_cell=2, "
      "region={shape=\"box\", lower=[0.6, 0.4], upper=[0.8, 0.6]}}]"};
  std::vector<Patch<2>> patches;
  auto split = validation::builtin_simulation<2>("two_disks.toml", overrides,
                                                 patch_points<2>(*world, {}, patches));
  distribute(*split, *world, std::move(patches));
  const long points = split->point_count();
  try {
    split->step();
    ADD_FAILURE() << "the step did not fail";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("CFL number"), std::string::npos) << e.what();
    // Every point has the same wave speed: every rank with points holds a fastest one.
    if (points == 0) {
      EXPECT_EQ(e.context().point, -1);
      EXPECT_EQ(e.context().body, "");
    } else {
      EXPECT_GE(e.context().point, 0);
      EXPECT_EQ(e.context().body, "block");
    }
  }
  std::vector<long> empty = {points == 0 ? 1L : 0L};
  world->sum(empty);
  if (world->size() == 3) {
    EXPECT_GE(empty[0], 1) << "no rank without points: the test tests nothing";
  }
}

TEST(DistributedRun, BreathingSphereAgreesWithOneProcess) {
  // A 3D membrane: mesh-connectivity frames of a sphere that every patch cuts.
  const Agreement a = compare_runs<3>("sphere_breathing.toml", {"solver.end_time=0.03"}, 400);
  expect_agreement(a);
  expect_halo_frames(a);
}

}  // namespace
}  // namespace pellicle
