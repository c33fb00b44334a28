#include "pellicle/dist/distributed_run.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "pellicle/core/error.hpp"
#include "pellicle/dist/halo_frames.hpp"
#include "pellicle/dist/halo_plan.hpp"
#include "pellicle/dist/migration.hpp"
#include "pellicle/dist/window_carrier.hpp"

namespace pellicle {

namespace {

//! Cell of x, clamped to the grid (points on or a round-off beyond a face belong to the cell
//! inside it).
template <int D>
IVec<D> cell_of(const Grid<D>& grid, const Vec<D>& x) {
  const Vec<D> xi = grid.to_cell_units(x);
  IVec<D> c;
  for (int d = 0; d < D; ++d) {
    const double f = std::floor(xi[d]) - Grid<D>::kGhost;
    c[d] = f < 0.0 ? 0 : f >= grid.cells()[d] ? grid.cells()[d] - 1 : static_cast<int>(f);
  }
  return c;
}

//! Patches of the grid for `ranks` ranks, weighing the points visit_points(visit) gives
//! (visit(x) for each), over the ranks that `sum` adds over.
template <int D, class VisitPoints>
std::vector<Patch<D>> split(const Grid<D>& grid, int ranks, VisitPoints&& visit_points,
                            const SumOverRanks& sum) {
  auto cells = [&](const std::function<void(const IVec<D>&, long)>& visit) {
    visit_points([&](const Vec<D>& x) { visit(cell_of(grid, x), 1); });
  };
  try {
    // Patches at least two ghost widths wide: a halo reaches only adjacent patches, and a
    // window that holds a ghost beyond a wall holds its mirror image too.
    return bisect_patches<D>(grid.cells(), ranks, 2 * Grid<D>::kGhost, cells, sum);
  } catch (const std::invalid_argument& e) {
    throw SetupError(e.what());
  }
}

//! The grid a rank stores: its patch's nodes and the layers its points' stencils reach.
template <int D>
Grid<D> window_of(const Grid<D>& grid, const Patch<D>& patch, int reach) {
  const IndexBox<D> box = touched_nodes(patch, grid.cells(), Grid<D>::kGhost, reach);
  // Of the owned ghost layers beyond the grid's sides, those the points reach.
  IndexBox<D> owned = owned_nodes(patch, grid.cells(), Grid<D>::kGhost);
  owned = {owned.first.cwiseMax(box.first), owned.last.cwiseMin(box.last)};
  const IVec<D> ghost = IVec<D>::Constant(Grid<D>::kGhost);
  return grid.window(box.first + ghost, box.last + ghost, owned.first + ghost, owned.last + ghost);
}

//! The cells shared with each other rank, as entries of the whole-grid cell fields.
template <int D>
std::vector<RankOrderSums::Neighbour> cell_neighbours(const std::vector<Patch<D>>& patches,
                                                      const IVec<D>& cells, int reach, int rank) {
  std::vector<RankOrderSums::Neighbour> out;
  for (auto& shared : shared_cells(patches, cells, reach, rank))
    out.push_back({shared.rank, std::move(shared.indices)});
  return out;
}

//! The patches as boxes in space (`grid`: the whole grid or a window of it), open where they
//! reach the domain's side.
template <int D>
std::vector<PatchBox<D>> patch_boxes(const std::vector<Patch<D>>& patches, const Grid<D>& grid) {
  constexpr double kOpen = std::numeric_limits<double>::infinity();
  std::vector<PatchBox<D>> boxes;
  for (const auto& p : patches) {
    PatchBox<D> box;
    for (int d = 0; d < D; ++d) {
      box.lower[d] = p.lower[d] == 0 ? -kOpen : grid.lower()[d] + p.lower[d] * grid.cell();
      box.upper[d] =
          p.upper[d] == grid.cells()[d] ? kOpen : grid.lower()[d] + p.upper[d] * grid.cell();
    }
    boxes.push_back(box);
  }
  return boxes;
}

}  // namespace

template <int D>
PatchRun<D>::PatchRun(const Communicator& world, std::vector<Patch<D>> patches,
                      const Grid<D>& window, int reach)
    : world_(world), reach_(reach) {
  use_patches(std::move(patches), window);
  start_imbalance_ = imbalance(patches_);
}

template <int D>
void PatchRun<D>::use_patches(std::vector<Patch<D>> patches, const Grid<D>& window) {
  patches_ = std::move(patches);
  const auto plan = halo_plan(patches_, window.cells(), Grid<D>::kGhost, reach_, world_.rank());
  halo_.emplace(world_, plan, window);
  // Patches that share nodes touch: a point that moved less than a cell goes to one of them.
  neighbours_.clear();
  for (const auto& shared : plan) neighbours_.push_back(shared.rank);
  cell_sums_.emplace(world_, cell_neighbours(patches_, window.cells(), reach_, world_.rank()));
  boxes_ = patch_boxes(patches_, window);
}

template <int D>
void PatchRun<D>::after_scatter(Simulation<D>& simulation, ScatteredFields fields) {
  const double start = omp_get_wtime();
  auto& grids = simulation.fields();
  for (int k = 0; k < grids.count(); ++k) {
    halo_->complete(grids.field(k), fields);
    doubles_sent_ += halo_->last_doubles_sent();
  }
  exchange_seconds_ += omp_get_wtime() - start;
}

template <int D>
void PatchRun<D>::after_node_sums(const std::vector<NodeArray>& arrays) {
  const double start = omp_get_wtime();
  halo_->complete(arrays);
  doubles_sent_ += halo_->last_doubles_sent();
  exchange_seconds_ += omp_get_wtime() - start;
}

template <int D>
void PatchRun<D>::after_cell_spread(Simulation<D>&, std::vector<double>& cells) {
  const double start = omp_get_wtime();
  cell_sums_->complete({{cells.data(), 1}});
  doubles_sent_ += cell_sums_->last_doubles_sent();
  exchange_seconds_ += omp_get_wtime() - start;
}

template <int D>
void PatchRun<D>::end_of_step(Simulation<D>& simulation) {
  const double start = omp_get_wtime();
  migrate(simulation);
  if (++steps_ % kBalanceCheck == 0) rebalance(simulation);
  points_ = simulation.points().size();
  exchange_seconds_ += omp_get_wtime() - start;
}

template <int D>
void PatchRun<D>::migrate(Simulation<D>& simulation) {
  auto& points = simulation.points();
  const long n = points.size();
  const PatchBox<D>& mine = boxes_[world_.rank()];
  // The points that left the patch, in ascending order (each thread's share in turn).
  leaving_.resize(omp_get_max_threads());
  for (auto& list : leaving_) list.clear();
#pragma omp parallel
  {
    auto& leaving = leaving_[omp_get_thread_num()];
#pragma omp for schedule(static)
    for (long p = 0; p < n; ++p)
      if (!mine.contains(points.position[p])) leaving.push_back({p, owner(points.position[p])});
  }
  for (std::size_t t = 1; t < leaving_.size(); ++t)
    leaving_[0].insert(leaving_[0].end(), leaving_[t].begin(), leaving_[t].end());
  const long sent = migrate_points(world_, leaving_[0], points, &neighbours_);
  migrated_ += sent;
  if (sent > 0 || points.size() != n) simulation.points_changed();
}

template <int D>
void PatchRun<D>::rebalance(Simulation<D>& simulation) {
  std::vector<long> total = {simulation.points().size()};
  world_.sum(total);
  const double most = world_.max(static_cast<double>(simulation.points().size()));
  const double limit = simulation.settings().rebalance;
  if (total[0] == 0) return;
  const double now = most * world_.size() / total[0] - 1.0;
  if (now <= limit) return;
  // The whole run's points, split anew; the points go to their new patches. A split that
  // would not cut the imbalance by half the limit is not worth the move (a few points in few
  // cells may not split any better).
  const Grid<D>& grid = simulation.grid();
  const auto& positions = simulation.points().position;
  std::vector<Patch<D>> patches = split(
      grid, world_.size(),
      [&](auto&& visit) {
        for (const auto& x : positions) visit(x);
      },
      [&](std::vector<long>& counts) { world_.sum(counts); });
  if (imbalance(patches) > now - 0.5 * limit) return;
  Grid<D> window = window_of(grid, patches[world_.rank()], reach_);
  use_patches(std::move(patches), window);
  const WindowCarrier<D> carrier(grid, window, &world_);
  simulation.use_grid_window(std::move(window), carrier);
  migrate(simulation);
  simulation.points_changed();
  ++rebalances_;
}

template <int D>
void PatchRun<D>::summary_figures(std::vector<std::pair<std::string, double>>& out) const {
  long frame_doubles = 0, gathered = 0;
  for (const auto* frames : frames_)
    frame_doubles += frames->doubles_sent(), gathered += frames->gathered_estimates();
  std::vector<double> sums = {static_cast<double>(doubles_sent_), static_cast<double>(migrated_),
                              static_cast<double>(points_), static_cast<double>(frame_doubles)};
  world_.sum_in_rank_order(sums);
  const double steps = std::max<long>(steps_, 1);
  out.emplace_back("distributed.halo_bytes_per_step", sums[0] * sizeof(double) / steps);
  out.emplace_back("distributed.exchange_seconds_per_step", world_.max(exchange_seconds_ / steps));
  out.emplace_back("distributed.migrated_points", sums[1]);
  out.emplace_back("distributed.rebalances", rebalances_);
  if (!frames_.empty()) {
    out.emplace_back("distributed.frames_bytes_per_step", sums[3] * sizeof(double) / steps);
    out.emplace_back("distributed.frames_gathered", gathered);
  }
  out.emplace_back("distributed.start_imbalance", start_imbalance_);
  const double most = world_.max(static_cast<double>(points_));
  out.emplace_back("distributed.imbalance",
                   sums[2] > 0.0 ? most * world_.size() / sums[2] - 1.0 : 0.0);
}

template <int D>
PointSelection<D> patch_points(const Communicator& world, SavedPoints<D> saved,
                               std::vector<Patch<D>>& patches) {
  return [&world, saved = std::move(saved), &patches](const Grid<D>& grid,
                                                      const std::vector<PlacedBody<D>>& bodies) {
    const int me = world.rank(), ranks = world.size();
    // The bodies the checkpoint holds (as many points as the case builds) continue from it.
    std::vector<char> continued(bodies.size(), 0);
    for (std::size_t b = 0; b < bodies.size(); ++b)
      if (saved.count) continued[b] = saved.count(bodies[b].name) == bodies[b].count;
    // Each point weighed once over the ranks: rank 0 walks the bodies as built, each rank
    // reads every ranks-th piece (rank 0 a checkpoint of one file).
    const PartFilter<D> share = [&](long piece, const Vec<D>&, const Vec<D>&) {
      return piece < 0 ? me == 0 : piece % ranks == me;
    };
    patches = split(
        grid, ranks,
        [&](auto&& visit) {
          for (std::size_t b = 0; b < bodies.size(); ++b) {
            if (continued[b])
              saved.for_each(bodies[b].name, share, [&](long, const Vec<D>& x) { visit(x); });
            else if (me == 0)
              bodies[b].walk([&](const Vec<D>& x) { visit(x); });
          }
        },
        [&](std::vector<long>& counts) { world.sum(counts); });
    const std::vector<PatchBox<D>> boxes = patch_boxes(patches, grid);
    std::vector<std::vector<char>> keep(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      keep[b].assign(bodies[b].count, 0);
      auto mark = [&](long k, const Vec<D>& x) { keep[b][k] = owner_of(boxes, x, me) == me; };
      if (continued[b]) {
        saved.for_each(bodies[b].name, parts_near_patch(patches, grid, me), mark);
      } else {
        long k = 0;
        bodies[b].walk([&](const Vec<D>& x) { mark(k++, x); });
      }
    }
    // Every point on exactly one rank.
    std::vector<long> kept(bodies.size(), 0);
    for (std::size_t b = 0; b < bodies.size(); ++b)
      kept[b] = std::count(keep[b].begin(), keep[b].end(), 1);
    world.sum(kept);
    for (std::size_t b = 0; b < bodies.size(); ++b)
      if (kept[b] != bodies[b].count)
        throw std::logic_error("body '" + bodies[b].name + "': the ranks keep " +
                               std::to_string(kept[b]) + " of its " +
                               std::to_string(bodies[b].count) + " points");
    return keep;
  };
}

template <int D>
PartFilter<D> parts_near_patch(const std::vector<Patch<D>>& patches, const Grid<D>& grid,
                               int rank) {
  const PatchBox<D> mine = patch_boxes(patches, grid)[rank];
  return [mine](long, const Vec<D>& lower, const Vec<D>& upper) {
    // Half-open like PatchBox::contains; a comparison with a value not finite keeps it.
    for (int d = 0; d < D; ++d)
      if (upper[d] < mine.lower[d] || lower[d] >= mine.upper[d]) return false;
    return true;
  };
}

template <int D>
const PatchRun<D>& distribute(Simulation<D>& simulation, const Communicator& world,
                              std::vector<Patch<D>> patches) {
  const Grid<D>& grid = simulation.grid();
  auto& points = simulation.points();
  const int reach = simulation.transfer().node_reach();
  if (reach > Grid<D>::kGhost)
    throw SetupError("the kernel reaches " + std::to_string(reach) +
                     " node layers beyond a cell, more than the grid's ghost layers");
  Grid<D> window = window_of(grid, patches[world.rank()], reach);
  auto hook = std::make_unique<PatchRun<D>>(world, std::move(patches), window, reach);
  hook->watch_frames(distribute_membrane_frames(
      world, points, points.columns.template find<double>(column_names::body_index), grid.cell()));
  const WindowCarrier<D> carrier(grid, window, nullptr);
  simulation.use_grid_window(std::move(window), carrier);
  simulation.points_changed();
  simulation.set_collective(&world);
  const PatchRun<D>& run = *hook;
  simulation.add_hook(std::move(hook));
  simulation.settle_state();  // built in part: the frames now see the whole membranes
  return run;
}

template class PatchRun<2>;
template class PatchRun<3>;
template const PatchRun<2>& distribute<2>(Simulation<2>&, const Communicator&,
                                          std::vector<Patch<2>>);
template const PatchRun<3>& distribute<3>(Simulation<3>&, const Communicator&,
                                          std::vector<Patch<3>>);
template PointSelection<2> patch_points<2>(const Communicator&, SavedPoints<2>,
                                           std::vector<Patch<2>>&);
template PointSelection<3> patch_points<3>(const Communicator&, SavedPoints<3>,
                                           std::vector<Patch<3>>&);
template PartFilter<2> parts_near_patch<2>(const std::vector<Patch<2>>&, const Grid<2>&, int);
template PartFilter<3> parts_near_patch<3>(const std::vector<Patch<3>>&, const Grid<3>&, int);

}  // namespace pellicle
