#include "pellicle/io/build.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "pellicle/geometry/fill.hpp"

namespace pellicle {

template <int D>
double point_volume(double cell, int points_per_cell, Kinematics kinematics, const Vec<D>& x) {
  const double v = std::pow(cell / points_per_cell, D);
  return kinematics == Kinematics::axisymmetric ? 2.0 * std::numbers::pi * x[0] * v : v;
}

namespace {

//! Where a body's points are and what each stands for: filled sub-cells of a region, or the
//! samples of a membrane (volume = length or area × thickness, IJNME §3: m = ρ Δs t).
template <int D>
std::vector<std::pair<Vec<D>, double>> body_points(const Case<D>& c, const BodySpec<D>& b) {
  std::vector<std::pair<Vec<D>, double>> out;
  const bool axisymmetric = c.settings.kinematics == Kinematics::axisymmetric;
  if (b.membrane) {
    for (std::size_t i = 0; i < b.membrane->points.size(); ++i) {
      const Vec<D>& x = b.membrane->points[i];
      const double v = b.membrane->measure[i] * b.thickness;
      out.emplace_back(x, axisymmetric ? 2.0 * std::numbers::pi * x[0] * v : v);
    }
  } else {
    for (const auto& x : fill_region<D>(*b.region, c.lower, c.upper, c.cell, b.points_per_cell))
      out.emplace_back(x, point_volume<D>(c.cell, b.points_per_cell, c.settings.kinematics, x));
  }
  return out;
}

template <int D>
std::shared_ptr<FrameEstimator<D>> frame_estimator(const Case<D>& c, const BodySpec<D>& b) {
  if (!b.membrane) return nullptr;
  FrameSetup<D> setup;
  setup.connectivity = b.membrane->connectivity;
  setup.grid_origin = c.lower;
  setup.cell = c.cell;
  setup.orientation = b.orientation;
  for (const auto& e : frame_estimators<D>())
    if (e.name == b.frames) return e.make(setup);
  return nullptr;
}

}  // namespace

template <int D>
std::unique_ptr<Simulation<D>> build_simulation(Case<D>& c) {
  Grid<D> grid(c.lower, c.upper, c.cell, c.faces);
  Particles<D> points;
  for (auto& material : c.materials) material->declare_columns(points);
  std::vector<InputProblem> problems;
  for (const auto& b : c.bodies) {
    const Material<D>& material = *c.materials[b.material];
    const auto positions = body_points(c, b);
    if (positions.empty()) {
      problems.push_back({b.where, "body.region",
                          "body '" + b.name + "': the region holds no point inside the grid"});
      continue;
    }
    bool outside = false;
    for (const auto& [x, v] : positions) outside = outside || !grid.contains(x);
    if (outside) {
      problems.push_back({b.where, "body.membrane",
                          "body '" + b.name + "': membrane points lie outside the grid"});
      continue;
    }
    auto check_index = [&](long index, const char* key) {
      if (index >= static_cast<long>(positions.size()))
        problems.push_back({b.where, key,
                            "body '" + b.name + "': no point " + std::to_string(index) +
                                " (it has " + std::to_string(positions.size()) + ")"});
    };
    for (const auto& entry : b.point_masses) check_index(entry.first, "body.point_masses");
    for (const auto& entry : b.point_velocities) check_index(entry.first, "body.point_velocities");
    points.bodies.push_back(
        {b.name, b.material, Vec<D>::Zero(), points.size(), points.size(), frame_estimator(c, b)});
    double body_mass = 0.0;
    Vec<D> first_moment = Vec<D>::Zero();
    const long last = b.initial_points.second < 0 ? static_cast<long>(positions.size()) - 1
                                                  : b.initial_points.second;
    if (last >= static_cast<long>(positions.size()))
      problems.push_back({b.where, "body.initial_strain.points",
                          "body '" + b.name + "': no point " + std::to_string(last) + " (it has " +
                              std::to_string(positions.size()) + ")"});
    const double density = b.density.value_or(material.density());
    for (const auto& [x, volume] : positions) points.add(x, b.velocity, density * volume, density);
    auto& body = points.bodies.back();
    InitialState<D> state;
    state.internal_energy = b.internal_energy;
    material.initialise(points, body.begin, body.end, state);
    state.strain = b.initial_strain.value_or(Sym<D>::Zero());
    state.stress = b.initial_stress;
    if (last < body.count())
      material.initialise(points, body.begin + b.initial_points.first, body.begin + last + 1,
                          state);
    // Point masses given explicitly (an end mass on a string) keep their point's volume.
    for (const auto& [index, mass] : b.point_masses) {
      if (index >= body.count()) continue;
      const long p = body.begin + index;
      points.mass[p] = mass;
      points.density[p] = mass / points.volume[p];
    }
    for (long p = body.begin; p < body.end; ++p) {
      body_mass += points.mass[p];
      first_moment += points.mass[p] * points.position[p];
    }
    body.applied_acceleration = b.external_force / body_mass;
    const Vec<D> center = b.center.value_or(first_moment / body_mass);
    for (long p = body.begin; p < body.end; ++p) {
      Vec3 r = Vec3::Zero();
      r.template head<D>() = points.position[p] - center;
      points.velocity[p] += b.angular_velocity.cross(r).template head<D>() +
                            b.velocity_gradient * r.template head<D>();
    }
    for (const auto& [index, velocity] : b.point_velocities)
      if (index < body.count()) points.velocity[body.begin + index] = velocity;
  }
  if (!problems.empty()) throw InputError(problems);

  int ppc = c.bodies.front().points_per_cell;
  for (const auto& b : c.bodies) {
    if (b.points_per_cell != ppc && c.kernel == "ugimp")
      throw InputError(b.where, "body.points_per_cell",
                       "uGIMP needs one particle size: every body must use the same "
                       "points_per_cell");
  }
  std::unique_ptr<Transfer<D>> transfer;
  for (const auto& k : kernel_choices<D>())
    if (k.name == c.kernel) transfer = k.make(c.transfer, ppc);

  std::vector<std::unique_ptr<Material<D>>> materials = std::move(c.materials);
  auto simulation =
      std::make_unique<Simulation<D>>(c.settings, std::move(grid), std::move(points),
                                      std::move(materials), std::move(transfer), c.gravity);
  simulation->set_contact(std::move(c.contact));
  return simulation;
}

template std::unique_ptr<Simulation<2>> build_simulation<2>(Case<2>&);
template std::unique_ptr<Simulation<3>> build_simulation<3>(Case<3>&);
template double point_volume<2>(double, int, Kinematics, const Vec<2>&);
template double point_volume<3>(double, int, Kinematics, const Vec<3>&);

}  // namespace pellicle
