#include "pellicle/mpm/simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "pellicle/core/error.hpp"
#include "pellicle/mpm/cell_density.hpp"

namespace pellicle {

template <int D>
Simulation<D>::Simulation(SimulationSettings settings, Grid<D> grid, Particles<D> points,
                          std::vector<std::unique_ptr<Material<D>>> materials,
                          std::unique_ptr<Transfer<D>> transfer, Vec<D> gravity)
    : settings_(settings),
      grid_(std::move(grid)),
      points_(std::move(points)),
      materials_(std::move(materials)),
      transfer_(std::move(transfer)),
      gravity_(gravity) {
  for (const auto& v : points_.velocity) max_speed_ = std::max(max_speed_, v.norm());
  if (points_.affine.size() != points_.position.size())
    points_.affine.assign(points_.position.size(), Mat<D>::Zero());
  rigid_velocity_.assign(points_.bodies.size(), Vec<D>::Zero());
  for (std::size_t b = 0; b < points_.bodies.size(); ++b) {
    if (!materials_[points_.bodies[b].material]->is_rigid()) continue;
    has_rigid_bodies_ = true;
    rigid_velocity_[b] = points_.velocity[points_.bodies[b].begin];
  }
  for (const auto& body : points_.bodies)
    if (materials_[body.material]->density_from_cells())
      cell_density_ranges_.emplace_back(body.begin, body.end);
  // Membrane stresses follow from their strains in their frames, fluid stresses from their
  // density and energy: settle them once before the first step (a zero step changes nothing
  // else).
  update_frames();
  velocity_gradient_.assign(points_.size(), Mat<D>::Zero());
  if (settings_.kinematics == Kinematics::axisymmetric) hoop_rate_.assign(points_.size(), 0.0);
  for (const auto& body : points_.bodies) {
    const auto& material = *materials_[body.material];
    if (material.is_membrane() || material.is_fluid())
      material.update(
          {points_, velocity_gradient_, hoop_rate_, 0.0, body.begin, body.end, grid_.cell()});
  }
}

template <int D>
void Simulation<D>::set_contact(std::unique_ptr<ContactModel<D>> model) {
  contact_ = std::move(model);
  fields_ = contact_
                ? std::make_unique<BodyFields<D>>(grid_, static_cast<int>(points_.bodies.size()))
                : nullptr;
}

template <int D>
void Simulation<D>::prescribe_rigid_nodes() {
  // The centre-of-mass field takes every rigid body's velocity; with a contact model each
  // body's own field takes only its own, so the others meet it through the contact rule.
  std::vector<std::pair<long, Vec<D>>> prescribed;
  std::vector<long> nodes;
  for (std::size_t b = 0; b < points_.bodies.size(); ++b) {
    const auto& body = points_.bodies[b];
    if (!materials_[body.material]->is_rigid()) continue;
    nodes.clear();
    transfer_->touched_nodes(grid_, body.begin, body.end, nodes);
    const std::size_t first = prescribed.size();
    for (long n : nodes) prescribed.emplace_back(n, points_.velocity[body.begin]);
    if (fields_)
      fields_->body_grid(static_cast<int>(b))
          .prescribe({prescribed.begin() + first, prescribed.end()});
  }
  grid_.prescribe(std::move(prescribed));
}

template <int D>
void Simulation<D>::restore_rigid_velocities() {
  // Rigid points keep their prescribed velocity exactly (FLIP would add the nodes' change).
  for (std::size_t b = 0; b < points_.bodies.size(); ++b) {
    const auto& body = points_.bodies[b];
    if (!materials_[body.material]->is_rigid()) continue;
    for (long p = body.begin; p < body.end; ++p) points_.velocity[p] = rigid_velocity_[b];
  }
}

template <int D>
void Simulation<D>::update_frames() {
  for (const auto& body : points_.bodies)
    if (body.frames)
      body.frames->estimate(points_.position, body.begin, body.end, points_.normal,
                            points_.tangent);
}

template <int D>
void Simulation<D>::step() {
  const double signal = max_signal_speed();
  const double dt = time_step(signal);
  cfl_number_ = dt * signal / grid_.cell();
  if (cfl_number_ > settings_.cfl_limit) {
    std::ostringstream what;
    what << "CFL number " << cfl_number_ << " > " << settings_.cfl_limit << " with dt = " << dt
         << " (this point is the fastest signal); reduce solver.dt or use solver.cfl";
    fail(fastest_point(), what.str());
  }
  transfer_->compute_stencils(points_, grid_);  // stencils
  if (has_rigid_bodies_) prescribe_rigid_nodes();
  if (settings_.scheme == UpdateScheme::usf) {  // to_grid (USF: stress first)
    transfer_->to_grid(points_, gravity_, grid_, false);
    grid_.velocities_from_momentum();
    update_materials(dt);
    transfer_->forces_to_grid(points_, gravity_, grid_);
  } else if (fields_) {
    fields_->to_grid(*transfer_, points_, gravity_, grid_);
  } else {
    transfer_->to_grid(points_, gravity_, grid_, true);
  }
  grid_.integrate(dt);  // grid
  if (fields_) {        // contact: each body's field, then the model's rule at shared nodes
    fields_->integrate(dt);
    contact_->resolve(*fields_, grid_, points_, dt, ContactPass::lagrangian);
  }
  PointFailure failure;  // to_points
  max_speed_ = fields_ ? fields_->to_points(*transfer_, dt, points_, failure)
                       : transfer_->to_points(grid_, dt, points_, failure);
  if (failure.point >= 0) fail(failure.point, failure.what);
  if (has_rigid_bodies_) restore_rigid_velocities();
  if (settings_.scheme == UpdateScheme::musl) {  // remap
    if (fields_) {
      fields_->remap(*transfer_, points_, grid_);
      contact_->resolve(*fields_, grid_, points_, dt, ContactPass::convected);
    } else {
      transfer_->remap(points_, grid_);
    }
  }
  if (settings_.scheme != UpdateScheme::usf) update_materials(dt);  // materials
  time_ += dt;
  last_dt_ = dt;
  ++step_;
  for (auto* observer : observers_) observer->after_step(*this);  // observe
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
long Simulation<D>::fastest_point() const {
  long fastest = 0;
  double top = -1.0;
  for (const auto& body : points_.bodies) {
    const double c =
        materials_[body.material]->max_signal_speed(points_, body.begin, body.end, grid_.cell());
    for (long p = body.begin; p < body.end; ++p) {
      const double s = c + points_.velocity[p].norm();
      if (s > top) top = s, fastest = p;
    }
  }
  return fastest;
}

template <int D>
double Simulation<D>::time_step(double signal_speed) const {
  double dt = settings_.fixed_dt;
  if (dt <= 0.0) dt = settings_.cfl_fraction * grid_.cell() / signal_speed;
  const double remaining = settings_.end_time - time_;
  // Land on the end time instead of overshooting it by a fraction of a step.
  if (remaining > 0.0 && remaining < dt * (1.0 + 1e-9)) dt = remaining;
  return dt;
}

template <int D>
double Simulation<D>::max_signal_speed() const {
  double wave = 0.0;
  for (const auto& body : points_.bodies)
    wave = std::max(wave, materials_[body.material]->max_signal_speed(points_, body.begin, body.end,
                                                                      grid_.cell()));
  return wave + max_speed_;
}

template <int D>
std::size_t Simulation<D>::memory_estimate_bytes() const {
  // Per point: position, velocity, affine, mass/volume/density/energy, stress, strain, body id, the
  // velocity-gradient scratch and the stencil. Per node: five fields, plus one private
  // scatter copy of mass, momentum and force per extra thread.
  const std::size_t per_point = sizeof(Vec<D>) * 2 + sizeof(Mat<D>) * 2 + 4 * sizeof(double) +
                                2 * sizeof(Sym<D>) + sizeof(int) + sizeof(double) +
                                transfer_->stencil_bytes();
  const std::size_t per_node = sizeof(double) + 4 * sizeof(Vec<D>);
  const std::size_t per_copy = sizeof(double) + 2 * sizeof(Vec<D>);
  const std::size_t threads = static_cast<std::size_t>(omp_get_max_threads());
  const std::size_t grids = 1 + (fields_ ? points_.bodies.size() : 0);  // contact: one per body
  return per_point * points_.size() +
         grid_.node_count() * (grids * per_node + (threads - 1) * per_copy);
}

template <int D>
void Simulation<D>::update_materials(double dt) {
  const long bad =
      fields_ ? fields_->point_kinematics(*transfer_, dt, points_, velocity_gradient_, hoop_rate_)
              : transfer_->point_kinematics(grid_, dt, points_, velocity_gradient_, hoop_rate_);
  if (bad >= 0) fail(bad, "non-positive or non-finite density");
  if (!cell_density_ranges_.empty())  // fluids with cell densities (thesis eq 4.6)
    cell_quadratic_density(grid_, settings_.kinematics == Kinematics::axisymmetric,
                           cell_density_ranges_, points_);
  update_frames();  // membrane frames at the current positions (thesis §5.3 step 7)
  for (const auto& body : points_.bodies) {
    const auto& material = *materials_[body.material];
    material.update(
        {points_, velocity_gradient_, hoop_rate_, dt, body.begin, body.end, grid_.cell()});
    const long invalid = material.first_invalid_point(points_, body.begin, body.end);
    if (invalid >= 0) fail(invalid, "non-finite or negative specific internal energy");
  }
}

template <int D>
SystemState<D> Simulation<D>::state() const {
  SystemState<D> s;
  const long n = points_.size();
  double kinetic = 0.0, gravitational = 0.0;
  double momentum[3] = {0.0, 0.0, 0.0};
#pragma omp parallel for schedule(static) reduction(+ : kinetic, gravitational, momentum[:3])
  for (long p = 0; p < n; ++p) {
    const double m = points_.mass[p];
    kinetic += 0.5 * m * points_.velocity[p].squaredNorm();
    gravitational -= m * gravity_.dot(points_.position[p]);
    for (int d = 0; d < D; ++d) momentum[d] += m * points_.velocity[p][d];
  }
  s.kinetic = kinetic + transfer_->affine_kinetic_energy(points_, grid_);
  s.gravitational = gravitational;
  for (int d = 0; d < D; ++d) s.momentum[d] = momentum[d];
  for (const auto& body : points_.bodies) {
    s.strain += materials_[body.material]->strain_energy(points_, body.begin, body.end);
    s.internal += materials_[body.material]->internal_energy(points_, body.begin, body.end);
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
    c.point = point - body.begin;
  }
  throw NumericalError(c, what);
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace pellicle
