#pragma once
//! A distributed run (DESIGN.md, "Distributed runs"): each rank builds only the points of its
//! patch (the patches split from every body's points as placed) and keeps the grid window they
//! reach, and a hook completes the node sums after each scatter (halo_sums.hpp) and moves
//! points that left the patch to its owner at the end of each step (migration.hpp). Cell fields
//! (contact's colour functions, cell densities) are completed like the node sums over the cells
//! patches share; membrane frames from each rank's points and the halo their estimator reaches,
//! or from the whole membrane where it must (halo_frames.hpp).
//! Reductions of whole-system quantities go through the communicator in rank order, so np = 1, 2, 3
//! … agree to round-off.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pellicle/dist/communicator.hpp"
#include "pellicle/dist/decomposition.hpp"
#include "pellicle/dist/halo_frames.hpp"
#include "pellicle/dist/halo_sums.hpp"
#include "pellicle/dist/migration.hpp"
#include "pellicle/mpm/builder.hpp"
#include "pellicle/mpm/simulation.hpp"

namespace pellicle {

//! A patch as a box in space, open where it reaches the domain's side.
template <int D>
struct PatchBox {
  Vec<D> lower, upper;
  bool contains(const Vec<D>& x) const {
    return (x.array() >= lower.array()).all() && (x.array() < upper.array()).all();
  }
};

//! The rank whose patch (of `boxes`) holds x; `me` when none does (x not finite: the step's
//! checks stop the run).
template <int D>
int owner_of(const std::vector<PatchBox<D>>& boxes, const Vec<D>& x, int me) {
  if (boxes[me].contains(x)) return me;
  for (std::size_t r = 0; r < boxes.size(); ++r)
    if (boxes[r].contains(x)) return static_cast<int>(r);
  return me;
}

template <int D>
class PatchRun final : public StepHook<D> {
 public:
  //! `window`: this rank's grid (Grid::window) of its patch's nodes and `reach` layers more.
  PatchRun(const Communicator& world, std::vector<Patch<D>> patches, const Grid<D>& window,
           int reach);

  void after_scatter(Simulation<D>& simulation, ScatteredFields fields) override;
  void after_node_sums(const std::vector<NodeArray>& arrays) override;
  void after_cell_spread(Simulation<D>& simulation, std::vector<double>& cells) override;
  void end_of_step(Simulation<D>& simulation) override;
  //! Every few steps the patches are split anew when the ranks' points are out of balance by
  //! more than the run's `rebalance` fraction (SimulationSettings).
  static constexpr long kBalanceCheck = 10;
  //! distributed.halo_bytes_per_step (all ranks' node and cell shares sent, per step),
  //! distributed.exchange_seconds_per_step (the slowest rank's time in halo sums and
  //! migration, waiting included), distributed.migrated_points (over the run) and
  //! distributed.imbalance (max / mean − 1 of the ranks' points, at the start and now),
  //! distributed.rebalances, and for membranes distributed.frames_bytes_per_step (all ranks'
  //! points sent for membrane frames, halo or whole body, per step) and
  //! distributed.frames_gathered (estimates made on a whole body gathered, per body).
  void summary_figures(std::vector<std::pair<std::string, double>>& out) const override;
  //! The membrane bodies' frame estimators, for their figures.
  void watch_frames(std::vector<const HaloFrames<D>*> frames) { frames_ = std::move(frames); }

  const std::vector<Patch<D>>& patches() const { return patches_; }
  //! The rank whose patch holds x (a patch at the domain's side reaches past it).
  int owner(const Vec<D>& x) const { return owner_of(boxes_, x, world_.rank()); }

 private:
  void use_patches(std::vector<Patch<D>> patches, const Grid<D>& window);
  //! Send the points that left the patch to their ranks, take in the others'.
  void migrate(Simulation<D>& simulation);
  //! Split the patches anew if the ranks' points are out of balance.
  void rebalance(Simulation<D>& simulation);

  const Communicator& world_;
  int reach_;
  std::vector<Patch<D>> patches_;
  std::vector<PatchBox<D>> boxes_;
  std::vector<int> neighbours_;  //!< the ranks whose patches share nodes with this one
  std::optional<HaloSums<D>> halo_;
  std::optional<RankOrderSums> cell_sums_;          //!< of the whole-grid cell fields
  std::vector<std::vector<LeavingPoint>> leaving_;  //!< per thread
  double start_imbalance_ = 0.0;
  long points_ = 0;  //!< this rank's, after the last step
  long steps_ = 0, doubles_sent_ = 0, migrated_ = 0, rebalances_ = 0;
  double exchange_seconds_ = 0.0;
  std::vector<const HaloFrames<D>*> frames_;
};

//! The checkpoint a distributed run continues from: `count(body)` is the number of points it
//! holds of the body of this name (none when it holds no such body); `for_each(body, read,
//! visit)` calls visit(index in the body as built, position) for its points of the body in
//! the parts `read` accepts.
template <int D>
struct SavedPoints {
  std::function<std::optional<long>(const std::string& body)> count;
  std::function<void(const std::string& body, const PartFilter<D>& read,
                     const std::function<void(long, const Vec<D>&)>& visit)>
      for_each;
};

//! The selection (SimulationBuilder::select_points) that builds only this rank's points: the
//! patches are split by recursive bisection of the point counts of every body, at the places
//! the bodies' points are built or, where `saved` holds them, where a checkpoint put them, and
//! this rank keeps the points of its patch. Each point is weighed by one rank: rank 0 walks the
//! bodies as built, each rank reads every size-th piece of the checkpoint; to keep its points
//! a rank reads only the pieces whose boxes meet its patch. The split goes to `patches`, for
//! distribute. The selection throws SetupError when the grid is too small for that many
//! patches.
template <int D>
PointSelection<D> patch_points(const Communicator& world, SavedPoints<D> saved,
                               std::vector<Patch<D>>& patches);

//! The parts of a checkpoint that can hold points of rank `rank`'s patch: those whose box
//! meets it (a part without a box, or with a point not finite, always).
template <int D>
PartFilter<D> parts_near_patch(const std::vector<Patch<D>>& patches, const Grid<D>& grid, int rank);

//! Complete a simulation built with patch_points' selection over the ranks of `world`: this
//! rank stores the grid window its patch's points reach and gets the PatchRun hook. Throws
//! SetupError when the kernel reaches beyond the grid's ghost layers. Returns the hook.
template <int D>
const PatchRun<D>& distribute(Simulation<D>& simulation, const Communicator& world,
                              std::vector<Patch<D>> patches);

extern template class PatchRun<2>;
extern template class PatchRun<3>;
extern template const PatchRun<2>& distribute<2>(Simulation<2>&, const Communicator&,
                                                 std::vector<Patch<2>>);
extern template const PatchRun<3>& distribute<3>(Simulation<3>&, const Communicator&,
                                                 std::vector<Patch<3>>);
extern template PointSelection<2> patch_points<2>(const Communicator&, SavedPoints<2>,
                                                  std::vector<Patch<2>>&);
extern template PointSelection<3> patch_points<3>(const Communicator&, SavedPoints<3>,
                                                  std::vector<Patch<3>>&);

}  // namespace pellicle
