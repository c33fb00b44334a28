#include "pellicle/dist/distributed_run.hpp"

#include <omp.h>

#include <cmath>
#include <limits>
#include <string>

#include "pellicle/core/error.hpp"
#include "pellicle/dist/halo_plan.hpp"
#include "pellicle/dist/migration.hpp"
#include "pellicle/mpm/boundary/rigid_bodies.hpp"

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

//! What distributed runs do not take yet, and why.
template <int D>
void refuse_unsupported(const Simulation<D>& s) {
  auto refuse = [](const std::string& what, const std::string& why) {
    throw SetupError(what + " cannot run on more than one rank yet: " + why +
                     "; run it without mpirun (or with -np 1)");
  };
  for (const auto& body : s.points().bodies) {
    const Material<D>& m = s.material(body.material);
    if (m.is_membrane())
      refuse("membrane body '" + body.name + "'",
             "its frames need neighbouring points that other ranks hold");
    if (m.density_from_cells())
      refuse("fluid body '" + body.name + "' (density_update from cells)",
             "its cell densities need the cells other ranks hold");
  }
  if (s.contact()) refuse("a contact model", "its body normals need cells other ranks hold");
  if (!s.enclosed().empty()) refuse("a body inside a membrane", "it needs the whole membrane");
  for (const auto& hook : s.hooks())
    if (dynamic_cast<const RigidBodies<D>*>(hook.get()))
      refuse("a rigid body", "its velocity is prescribed from points that other ranks hold");
}

}  // namespace

template <int D>
PatchRun<D>::PatchRun(const Communicator& world, std::vector<Patch<D>> patches,
                      const Grid<D>& window)
    : world_(world),
      patches_(std::move(patches)),
      halo_(world, halo_plan(patches_, window.cells(), Grid<D>::kGhost, world.rank()), window) {
  statistics_.imbalance = imbalance(patches_);
  constexpr double kOpen = std::numeric_limits<double>::infinity();
  for (const auto& p : patches_) {
    Box box;
    for (int d = 0; d < D; ++d) {
      box.lower[d] = p.lower[d] == 0 ? -kOpen : window.lower()[d] + p.lower[d] * window.cell();
      box.upper[d] =
          p.upper[d] == window.cells()[d] ? kOpen : window.lower()[d] + p.upper[d] * window.cell();
    }
    boxes_.push_back(box);
  }
}

template <int D>
int PatchRun<D>::owner(const Vec<D>& x) const {
  const int me = world_.rank();
  if (boxes_[me].contains(x)) return me;
  for (std::size_t r = 0; r < boxes_.size(); ++r)
    if (boxes_[r].contains(x)) return static_cast<int>(r);
  return me;  // not finite: the step's checks stop the run
}

template <int D>
void PatchRun<D>::after_scatter(Simulation<D>& simulation, ScatteredFields fields) {
  auto& grids = simulation.fields();
  for (int k = 0; k < grids.count(); ++k) {
    halo_.complete(grids.field(k), fields);
    halo_this_step_ += halo_.last_doubles_sent();
  }
}

template <int D>
void PatchRun<D>::end_of_step(Simulation<D>& simulation) {
  auto& points = simulation.points();
  const long n = points.size();
  const Box& mine = boxes_[world_.rank()];
  // The points that left the patch, in ascending order (each thread's share in turn).
  leaving_.resize(omp_get_max_threads());
#pragma omp parallel
  {
    auto& leaving = leaving_[omp_get_thread_num()];
    leaving.clear();
#pragma omp for schedule(static)
    for (long p = 0; p < n; ++p)
      if (!mine.contains(points.position[p])) leaving.push_back({p, owner(points.position[p])});
  }
  for (std::size_t t = 1; t < leaving_.size(); ++t)
    leaving_[0].insert(leaving_[0].end(), leaving_[t].begin(), leaving_[t].end());
  const long sent = migrate_points(world_, leaving_[0], points);
  statistics_.migrated += sent;
  if (sent > 0 || points.size() != n) simulation.points_changed();
  statistics_.halo_doubles_per_step = halo_this_step_;
  halo_this_step_ = 0;
}

template <int D>
const PatchRun<D>& distribute(Simulation<D>& simulation, const Communicator& world) {
  refuse_unsupported(simulation);
  const Grid<D>& grid = simulation.grid();
  auto& points = simulation.points();
  CellCounts<D> counts{grid.cells(), {}};
  long cells = 1;
  for (int d = 0; d < D; ++d) cells *= grid.cells()[d];
  counts.points.assign(cells, 0);
  for (const auto& x : points.position) {
    const IVec<D> c = cell_of(grid, x);
    long flat = c[D - 1];
    for (int d = D - 2; d >= 0; --d) flat = flat * grid.cells()[d] + c[d];
    ++counts.points[flat];
  }
  std::vector<Patch<D>> patches;
  try {
    // Patches at least two ghost widths wide: a halo reaches only adjacent patches, and a
    // window that holds a ghost beyond a wall holds its mirror image too.
    patches = bisect_patches(counts, world.size(), 2 * Grid<D>::kGhost);
  } catch (const std::invalid_argument& e) {
    throw SetupError(e.what());
  }
  const NodeBox<D> box = touched_nodes(patches[world.rank()], grid.cells(), Grid<D>::kGhost);
  const IVec<D> ghost = IVec<D>::Constant(Grid<D>::kGhost);
  const Grid<D> window = grid.window(box.first + ghost, box.last + ghost);
  auto hook = std::make_unique<PatchRun<D>>(world, std::move(patches), window);
  std::vector<char> keep(points.size());
  for (long p = 0; p < points.size(); ++p)
    keep[p] = hook->owner(points.position[p]) == world.rank();
  keep_points(keep, points);
  simulation.use_grid_window(window);
  simulation.points_changed();
  simulation.set_collective(&world);
  const PatchRun<D>& run = *hook;
  simulation.add_hook(std::move(hook));
  return run;
}

template class PatchRun<2>;
template class PatchRun<3>;
template const PatchRun<2>& distribute<2>(Simulation<2>&, const Communicator&);
template const PatchRun<3>& distribute<3>(Simulation<3>&, const Communicator&);

}  // namespace pellicle
