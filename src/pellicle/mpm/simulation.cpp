#include "pellicle/mpm/simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "pellicle/core/error.hpp"
#include "pellicle/core/log.hpp"
#include "pellicle/core/ordered_sum.hpp"
#include "pellicle/mpm/boundary/rigid_bodies.hpp"
#include "pellicle/mpm/cell_density.hpp"

namespace pellicle {

template <int D>
Simulation<D>::Simulation(SimulationSettings settings, Grid<D> grid, Particles<D> points,
                          std::vector<std::unique_ptr<Material<D>>> materials,
                          std::unique_ptr<Transfer<D>> transfer, Vec<D> gravity)
    : settings_(settings),
      fields_(std::move(grid)),
      points_(std::move(points)),
      materials_(std::move(materials)),
      transfer_(std::move(transfer)),
      scheme_(make_scheme(settings.scheme)),
      gravity_(gravity) {
  if (points_.bodies.empty()) throw SetupError("a simulation needs at least one body");
  for (const auto& body : points_.bodies) {
    if (body.count() <= 0 && body.built <= 0)
      throw SetupError("body '" + body.name + "' has no point");
    if (body.material < 0 || body.material >= material_count())
      throw SetupError("body '" + body.name + "' names material " + std::to_string(body.material) +
                       " of " + std::to_string(material_count()));
  }
  for (auto& material : materials_) material->declare_columns(points_);
  transfer_->declare_columns(points_);
  normal_ = points_.columns.template find<Vec<D>>(column_names::normal);
  tangent_ = points_.columns.template find<Vec<D>>(column_names::tangent);
  for (const auto& v : points_.velocity) max_speed_ = std::max(max_speed_, v.norm());

  std::vector<int> rigid;
  std::vector<Vec<D>> rigid_velocity;
  for (std::size_t b = 0; b < points_.bodies.size(); ++b) {
    const auto& body = points_.bodies[b];
    const auto& material = *materials_[body.material];
    if (material.is_rigid()) {
      rigid.push_back(static_cast<int>(b));
      rigid_velocity.push_back(body.count() >= body.built ? points_.velocity[body.begin]
                                                          : body.start_velocity);
    }
    if (material.is_membrane() && !(body.frames && normal_.valid()))
      throw SetupError("membrane body '" + body.name + "' needs a frame estimator");
  }
  if (!rigid.empty())
    add_hook(std::make_unique<RigidBodies<D>>(std::move(rigid), std::move(rigid_velocity)));

  points_changed();
  // Built in part (a distributed run's rank, whose points carry their index in their body):
  // the ranks settle together once they are connected.
  if (!points_.columns.template find<double>(column_names::body_index).valid()) settle_state();
}

template <int D>
void Simulation<D>::settle_state() {
  if (settled_) return;
  settled_ = true;
  // Membrane stresses follow from their strains in their frames, fluid stresses from their
  // density and energy: settle them once before the first step (a zero step changes nothing
  // else).
  update_frames();
  for (int b = 0; b < static_cast<int>(points_.bodies.size()); ++b) {
    const auto& body = points_.bodies[b];
    const auto& material = *materials_[body.material];
    if (!material.stress_from_state()) continue;
    const std::vector<Mat<D>> no_gradient(body.count(), Mat<D>::Zero());
    const std::vector<double> no_hoop_rate(body.count(), 0.0);
    material.update({points_,
                     {no_gradient.data(), body.begin},
                     {no_hoop_rate.data(), body.begin},
                     0.0,
                     body.begin,
                     body.end,
                     this->grid().cell()});
  }
}

template <int D>
void Simulation<D>::points_changed() {
  settled_wave_speed_.reset();
  blocks_.clear();
  cell_density_ranges_.clear();
  std::vector<PointRange> ranges;
  for (int b = 0; b < static_cast<int>(points_.bodies.size()); ++b) {
    const auto& body = points_.bodies[b];
    for (long first = body.begin; first < body.end; first += kBlockPoints)
      blocks_.push_back({b, first, std::min(first + kBlockPoints, body.end)});
    if (materials_[body.material]->density_from_cells())
      cell_density_ranges_.emplace_back(body.begin, body.end);
    ranges.push_back({body.begin, body.end});
  }
  block_checks_.resize(blocks_.size());
  fields_.set_body_ranges(ranges);
}

template <int D>
void Simulation<D>::use_grid_window(Grid<D> window, const NodeCarrier& carrier) {
  fields_.replace_grid(std::move(window));
  for (auto& hook : hooks_) hook->grid_replaced(carrier);
}

template <int D>
void Simulation<D>::add_hook(std::unique_ptr<StepHook<D>> hook) {
  if (hook->needs_body_fields()) {
    if (!scheme_->allows_body_fields())
      throw SetupError(std::string("contact models work with the \"musl\" or \"usl\" scheme, "
                                   "not \"") +
                       scheme_->name() +
                       "\": it updates the stress from mapped velocities no "
                       "contact rule has corrected");
    if (fields_.per_body()) throw SetupError("only one contact model per simulation");
    std::vector<PointRange> ranges;
    for (const auto& body : points_.bodies) ranges.push_back({body.begin, body.end});
    fields_.use_body_fields(ranges);
  }
  hooks_.push_back(std::move(hook));
}

template <int D>
void Simulation<D>::set_contact(std::unique_ptr<ContactModel<D>> model) {
  if (!model) return;
  if (contact_) throw SetupError("only one contact model per simulation");
  ContactModel<D>* raw = model.get();
  add_hook(std::move(model));
  contact_ = raw;
}

template <int D>
void Simulation<D>::update_frames() {
  for (const auto& body : points_.bodies)
    if (body.frames)
      body.frames->estimate(points_.position, body.begin, body.end, points_[normal_],
                            points_[tangent_]);
}

template <int D>
void Simulation<D>::step() {
  const double dt = time_step();  // 1 time_step
  stencils();                     // 2 stencils
  scheme_->advance(*this, dt);    // 3–7 to_grid, grid, to_points, remap, materials
  for (auto& hook : hooks_) hook->end_of_step(*this);
  observe(dt);  // 8 observe
}

template <int D>
double Simulation<D>::time_step() {
  // The materials stage of the last step measured it while updating the points.
  double wave = settled_wave_speed_ ? *settled_wave_speed_ : local_max_wave_speed();
  settled_wave_speed_.reset();
  const double own_wave = wave, own_speed = max_speed_;  // this process's points'
  if (collective_) {                                     // one reduction for both speeds
    std::vector<double> speeds{wave, max_speed_};
    collective_->max(speeds);
    wave = speeds[0], max_speed_ = speeds[1];
  }
  const double dt = time_step(wave + max_speed_);
  // Thesis §8.4 (eqs 8.39–8.41): the Lagrangian step is stable up to Δt = h/c with points at
  // cell sides and 2h/c at cell centres, so the stability number is c Δt / h; the point speed
  // does not enter it. A point moving more than the same fraction of a cell per step is a
  // separate failure: the stencils and the grid update no longer see where it goes.
  cfl_number_ = dt * wave / grid().cell();
  const double transport = dt * max_speed_ / grid().cell();
  if (cfl_number_ > settings_.cfl_limit || transport > settings_.cfl_limit) {
    const bool waves = cfl_number_ > settings_.cfl_limit;
    std::ostringstream what;
    if (waves)
      what << "CFL number c dt / h = " << cfl_number_
           << " > solver.cfl_limit = " << settings_.cfl_limit << " with dt = " << dt
           << " and c = " << wave << " at this point; reduce solver.dt or use solver.cfl";
    else
      what << "this point moves " << transport
           << " cells per step (|v| dt / h > solver.cfl_limit = " << settings_.cfl_limit
           << ", dt = " << dt << "); reduce solver.dt or use solver.cfl";
    // Every rank of a distributed run finds the step too long; the ranks holding the fastest
    // point name it, the others (a rank may hold no points at all) name none.
    const bool here = waves ? own_wave >= wave : own_speed >= max_speed_;
    fail(here ? fastest_point(waves) : -1, what.str());
  }
  return dt;
}

template <int D>
void Simulation<D>::stencils() {
  transfer_->compute_stencils(points_, grid(), fields_.body_ranges());
}

template <int D>
void Simulation<D>::to_grid(bool forces) {
  fields_.for_each_grid([](Grid<D>& g) { g.clear_prescribed(); });  // hooks set them anew
  for (int k = 0; k < fields_.count(); ++k)
    transfer_->to_grid(points_, gravity_, fields_.field(k), forces, fields_.points(k));
  scattered({true, true, forces});
  for (auto& hook : hooks_) hook->after_to_grid(*this);
}

template <int D>
void Simulation<D>::scattered(ScatteredFields scattered) {
  for (auto& hook : hooks_) hook->after_scatter(*this, scattered);
  fields_.sum_to_centre_of_mass(scattered.mass, scattered.force);
}

template <int D>
void Simulation<D>::grid_velocities() {
  fields_.for_each_grid([](Grid<D>& g) { g.velocities_from_momentum(); });
}

template <int D>
void Simulation<D>::forces_to_grid() {
  for (int k = 0; k < fields_.count(); ++k)
    transfer_->forces_to_grid(points_, gravity_, fields_.field(k), fields_.points(k));
  scattered({false, false, true});
}

template <int D>
void Simulation<D>::grid(double dt) {
  fields_.for_each_grid([dt](Grid<D>& g) { g.integrate(dt); });
  for (auto& hook : hooks_) hook->after_grid_update(*this, GridPass::lagrangian, dt);
}

template <int D>
void Simulation<D>::to_points(double dt) {
  move_points(dt, {});
}

template <int D>
void Simulation<D>::to_points_and_remap(double dt) {
  const bool separate = std::any_of(hooks_.begin(), hooks_.end(),
                                    [](const auto& hook) { return hook->sets_point_velocities(); });
  move_points(dt, {.remap = !separate});
  if (separate)
    for (int k = 0; k < fields_.count(); ++k)
      transfer_->remap(points_, fields_.field(k), fields_.points(k));
  convected_velocities(dt);
}

template <int D>
void Simulation<D>::to_points_and_gradients(double dt) {
  settled_gradient_.resize(points_.size());
  if (settings_.kinematics == Kinematics::axisymmetric) settled_hoop_rate_.resize(points_.size());
  move_points(dt, {false, settled_gradient_.data(),
                   settled_hoop_rate_.empty() ? nullptr : settled_hoop_rate_.data()});
  gradients_settled_ = true;
}

template <int D>
void Simulation<D>::move_points(double dt, const PointPassExtras<D>& extras) {
  PointFailure failure;
  max_speed_ = 0.0;
  for (int k = 0; k < fields_.count() && failure.point < 0; ++k)
    max_speed_ = std::max(max_speed_, transfer_->to_points(fields_.field(k), dt, points_, failure,
                                                           fields_.points(k), extras));
  if (failure.point >= 0) fail(failure.point, failure.what);
  for (auto& hook : hooks_) hook->after_to_points(*this);
}

template <int D>
void Simulation<D>::convected_velocities(double dt) {
  for (auto& hook : hooks_) hook->after_scatter(*this, {false, true, false});
  for (int k = 0; k < fields_.count(); ++k) fields_.field(k).velocities_from_momentum();
  if (fields_.per_body()) {
    fields_.sum_to_centre_of_mass(false, false);
    fields_.centre_of_mass().velocities_from_momentum();
  }
  for (auto& hook : hooks_) hook->after_grid_update(*this, GridPass::convected, dt);
}

template <int D>
void Simulation<D>::materials(double dt) {
  update_frames();  // membrane frames at the new positions (thesis §5.3 step 7)
  if (!cell_density_ranges_.empty()) settle_cell_densities(dt);
  const bool axisymmetric = settings_.kinematics == Kinematics::axisymmetric;
  const int threads = omp_get_max_threads();
  if (static_cast<int>(block_scratch_.size()) < threads) {
    block_scratch_.resize(threads);
    for (auto& scratch : block_scratch_) {
      scratch.gradient.resize(kBlockPoints);
      if (axisymmetric) scratch.hoop_rate.resize(kBlockPoints);
    }
  }
  // Per block of points, the kinematics, the material update, the block's largest signal
  // speed (the next step's CFL speed) and the material's check of the block's points, so the
  // velocity gradient is used while it is in the cache and never stored for every point, and
  // no pass over the points of its own finds the signal speed or checks the state. The blocks
  // go to whichever thread is free (a block's results do not depend on the thread, and the
  // minimum and maximum below on no order), so a thread slowed down by something else on its
  // core does not hold the others at the stage's end.
  long first_bad = std::numeric_limits<long>::max();
  double wave = 0.0;
#pragma omp parallel reduction(min : first_bad) reduction(max : wave)
  {
    BlockScratch& scratch = block_scratch_[omp_get_thread_num()];
#pragma omp for schedule(dynamic)
    for (long i = 0; i < static_cast<long>(blocks_.size()); ++i) {
      const PointBlock& block = blocks_[i];
      const auto& body = points_.bodies[block.body];
      const Material<D>& material = *materials_[body.material];
      block_checks_[i] = {};
      BlockValues<Mat<D>> gradient(settled_gradient_);
      BlockValues<double> hoop_rate(settled_hoop_rate_);
      if (!material.density_from_cells()) {
        const long bad =
            gradients_settled_
                ? settled_continuity(dt, block.begin, block.end)
                : transfer_->point_kinematics(fields_.field(fields_.per_body() ? block.body : 0),
                                              dt, points_, block.begin, block.end,
                                              scratch.gradient.data(), scratch.hoop_rate.data());
        if (bad >= 0) {
          first_bad = std::min(first_bad, bad);
          continue;
        }
        if (!gradients_settled_) {
          gradient = {scratch.gradient.data(), block.begin};
          hoop_rate = {scratch.hoop_rate.data(), block.begin};
        }
      }
      if (time_ >= body.cut_at) {  // a cut tether: its points carry mass but no stress
        std::fill(points_.stress.begin() + block.begin, points_.stress.begin() + block.end,
                  Sym<D>::Zero());
      } else {
        material.update({points_, gradient, hoop_rate, dt, block.begin, block.end, grid().cell()});
        block_checks_[i] = material.check_points(points_, block.begin, block.end, grid().cell());
      }
      wave = std::max(wave, wave_speed(block));
    }
  }
  gradients_settled_ = false;
  if (first_bad != std::numeric_limits<long>::max())
    fail(first_bad, "non-positive or non-finite density");
  settled_wave_speed_ = wave;
  check_materials();
}

template <int D>
long Simulation<D>::settled_continuity(double dt, long begin, long end) {
  return continuity_update<D>(
      points_, settled_gradient_.data() + begin,
      settled_hoop_rate_.empty() ? nullptr : settled_hoop_rate_.data() + begin, dt, begin, end);
}

template <int D>
void Simulation<D>::settle_cell_densities(double dt) {
  // Fluids with cell densities (thesis eq 4.6): the velocity gradients of their points first,
  // kept for the materials stage, then their densities from the cells.
  settled_gradient_.resize(points_.size());
  if (settings_.kinematics == Kinematics::axisymmetric) settled_hoop_rate_.resize(points_.size());
  long first_bad = std::numeric_limits<long>::max();
#pragma omp parallel for schedule(dynamic) reduction(min : first_bad)  // as in materials()
  for (long i = 0; i < static_cast<long>(blocks_.size()); ++i) {
    const PointBlock& block = blocks_[i];
    if (!materials_[points_.bodies[block.body].material]->density_from_cells()) continue;
    const long bad =
        gradients_settled_
            ? settled_continuity(dt, block.begin, block.end)
            : transfer_->point_kinematics(
                  fields_.field(fields_.per_body() ? block.body : 0), dt, points_, block.begin,
                  block.end, settled_gradient_.data() + block.begin,
                  settled_hoop_rate_.empty() ? nullptr : settled_hoop_rate_.data() + block.begin);
    if (bad >= 0) first_bad = std::min(first_bad, bad);
  }
  if (first_bad != std::numeric_limits<long>::max())
    fail(first_bad, "non-positive or non-finite density");
  cell_quadratic_density(
      grid(), settings_.kinematics == Kinematics::axisymmetric, cell_density_ranges_, points_,
      [this](std::vector<double>& cells) { complete_cell_sums(cells); }, cell_density_work_);
}

template <int D>
void Simulation<D>::check_materials() {
  // The blocks of a body are consecutive and in point order: its first invalid point is the
  // first block's that has one, its thinnest point the first block's with the widest spacing.
  std::size_t i = 0;
  for (int b = 0; b < static_cast<int>(points_.bodies.size()); ++b) {
    typename Material<D>::PointCheck check;
    for (; i < blocks_.size() && blocks_[i].body == b; ++i) {
      const auto& block = block_checks_[i];
      if (check.invalid < 0 && block.invalid >= 0)
        check.invalid = block.invalid, check.why = block.why;
      if (block.spacing > check.spacing)
        check.spacing = block.spacing, check.thinnest = block.thinnest;
    }
    const auto& body = points_.bodies[b];
    if (check.invalid >= 0) fail(check.invalid, check.why);
    if (check.spacing > 1.0 && !thinned_.count(body.name)) {
      thinned_.insert(body.name);  // once per body
      char text[300];
      std::snprintf(text, sizeof text,
                    "at t = %g body '%s' has thinned to fewer than one point per cell along its "
                    "stretch (point %ld is %.2f cells from its neighbours): the gas there is not "
                    "resolved; use more points per cell or a finer grid (docs/theory/gas.md)",
                    time_, body.name.c_str(), check.thinnest - body.begin, check.spacing);
      log_warning(text);
    }
  }
}

template <int D>
void Simulation<D>::observe(double dt) {
  time_ += dt;
  last_dt_ = dt;
  ++step_;
  for (auto* observer : observers_) observer->after_step(*this);
}

template <int D>
void Simulation<D>::restore_clock(double time, long step, double last_dt, double max_speed) {
  time_ = time;
  step_ = step;
  last_dt_ = last_dt;
  max_speed_ = max_speed;
  settled_wave_speed_.reset();  // the points' state was just read in
}

template <int D>
void Simulation<D>::run(long max_steps) {
  while (!finished() && (max_steps <= 0 || step_ < max_steps)) step();
}

template <int D>
bool Simulation<D>::finished() const {
  // A relative tolerance keeps round-off in Σ Δt from adding a sliver of a step at the end.
  return time_ >= settings_.end_time * (1.0 - 1e-12);
}

template <int D>
double Simulation<D>::planned_dt() const {
  return time_step(max_signal_speed());
}

template <int D>
long Simulation<D>::fastest_point(bool waves) const {
  long fastest = -1;
  double top = -1.0;
  for (const auto& body : points_.bodies) {
    if (waves) {  // point by point (a failure is rare; the step asks per body)
      for (long p = body.begin; p < body.end; ++p) {
        const double c =
            materials_[body.material]->max_signal_speed(points_, p, p + 1, grid().cell());
        if (c > top) top = c, fastest = p;
      }
      continue;
    }
    for (long p = body.begin; p < body.end; ++p)
      if (points_.velocity[p].norm() > top) top = points_.velocity[p].norm(), fastest = p;
  }
  return fastest;
}

template <int D>
double Simulation<D>::time_step(double signal_speed) const {
  double dt = settings_.fixed_dt;
  if (dt <= 0.0) dt = settings_.cfl_fraction * grid().cell() / signal_speed;
  const double remaining = settings_.end_time - time_;
  // Land on the end time instead of overshooting it by a fraction of a step.
  if (remaining > 0.0 && remaining < dt * (1.0 + 1e-9)) dt = remaining;
  return dt;
}

template <int D>
double Simulation<D>::local_max_wave_speed() const {
  double wave = 0.0;
#pragma omp parallel for schedule(static) reduction(max : wave)
  for (long i = 0; i < static_cast<long>(blocks_.size()); ++i)
    wave = std::max(wave, wave_speed(blocks_[i]));
  return wave;
}

template <int D>
double Simulation<D>::wave_speed(const PointBlock& block) const {
  const Material<D>& material = *materials_[points_.bodies[block.body].material];
  return material.max_signal_speed(points_, block.begin, block.end, grid().cell());
}

template <int D>
double Simulation<D>::max_wave_speed() const {
  return global_max(local_max_wave_speed());
}

template <int D>
double Simulation<D>::max_signal_speed() const {
  return max_wave_speed() + global_max(max_speed_);
}

template <int D>
std::size_t Simulation<D>::memory_estimate_bytes() const {
  // Per point: the common columns, the declared ones, the stencil anchor, and the velocity
  // gradients kept by to_points (USL) or for fluids with cell densities. Per node: the grid fields,
  // plus one private scatter copy of mass, momentum and force per extra thread. Per thread: a
  // block's velocity gradients.
  const bool axisymmetric = settings_.kinematics == Kinematics::axisymmetric;
  const std::size_t gradient = sizeof(Mat<D>) + (axisymmetric ? sizeof(double) : 0);
  const std::size_t per_point =
      sizeof(Vec<D>) * 2 + 3 * sizeof(double) + sizeof(Sym<D>) + sizeof(int) +
      points_.columns.bytes_per_point() + transfer_->stencil_bytes() +
      (cell_density_ranges_.empty() && !scheme_->keeps_gradients() ? 0 : gradient);
  const std::size_t per_copy = sizeof(double) + 2 * sizeof(Vec<D>);
  const std::size_t threads = static_cast<std::size_t>(omp_get_max_threads());
  return per_point * points_.size() +
         grid().node_count() * (fields_.bytes_per_node() + (threads - 1) * per_copy) +
         threads * kBlockPoints * gradient;
}

template <int D>
SystemState<D> Simulation<D>::state() const {
  SystemState<D> s;
  const long n = points_.size();
  // Kinetic and gravitational energy, momentum.
  const auto sums = ordered_sums<2 + D>(0, n, [&](long p, std::array<double, 2 + D>& sum) {
    const double m = points_.mass[p];
    sum[0] += 0.5 * m * points_.velocity[p].squaredNorm();
    sum[1] -= m * gravity_.dot(points_.position[p]);
    for (int d = 0; d < D; ++d) sum[2 + d] += m * points_.velocity[p][d];
  });
  s.kinetic = sums[0] + transfer_->affine_kinetic_energy(points_, grid());
  s.gravitational = sums[1];
  for (int d = 0; d < D; ++d) s.momentum[d] = sums[2 + d];
  for (const auto& body : points_.bodies) {
    s.strain += materials_[body.material]->strain_energy(points_, body.begin, body.end);
    s.internal += materials_[body.material]->internal_energy(points_, body.begin, body.end);
  }
  if (collective_) {
    std::vector<double> sums{s.kinetic, s.strain, s.internal, s.gravitational};
    for (int d = 0; d < D; ++d) sums.push_back(s.momentum[d]);
    collective_->sum_in_rank_order(sums);
    s.kinetic = sums[0], s.strain = sums[1], s.internal = sums[2], s.gravitational = sums[3];
    for (int d = 0; d < D; ++d) s.momentum[d] = sums[4 + d];
  }
  return s;
}

template <int D>
void Simulation<D>::fail(long point, const std::string& what) const {
  NumericalError::Context c;
  c.time = time_;
  c.step = step_;
  if (point >= 0) {
    const auto& body = points_.bodies[points_.body[point]];
    c.body = body.name;
    // A distributed run's points carry their index in the body as built.
    const Column<double> built = points_.columns.template find<double>(column_names::body_index);
    c.point = built.valid() ? static_cast<long>(points_[built][point]) : point - body.begin;
  }
  throw NumericalError(c, what);
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace pellicle
