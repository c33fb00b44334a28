#include "pellicle/mpm/builder.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <Eigen/Geometry>

#include "pellicle/core/log.hpp"
#include "pellicle/geometry/enclosure.hpp"
#include "pellicle/geometry/fill.hpp"

namespace pellicle {

namespace {
std::string describe(const std::vector<SetupProblem>& problems) {
  std::string all;
  for (const auto& p : problems) all += (all.empty() ? "" : "\n") + p.key + ": " + p.message;
  return all;
}
}  // namespace

BuildError::BuildError(std::vector<SetupProblem> problems)
    : SetupError(describe(problems)), problems_(std::move(problems)) {}

template <int D>
double point_volume(double cell, int points_per_cell, Kinematics kinematics, const Vec<D>& x) {
  const double v = std::pow(cell / points_per_cell, D);
  return kinematics == Kinematics::axisymmetric ? 2.0 * std::numbers::pi * x[0] * v : v;
}

template <int D>
SimulationBuilder<D>::SimulationBuilder(const Vec<D>& lower, const Vec<D>& upper, double cell,
                                        const FaceConditions<D>& faces)
    : lower_(lower), upper_(upper), cell_(cell), faces_(faces) {}

template <int D>
SimulationBuilder<D>& SimulationBuilder<D>::settings(const SimulationSettings& settings) {
  settings_ = settings;
  return *this;
}

template <int D>
SimulationBuilder<D>& SimulationBuilder<D>::kernel(const std::string& name,
                                                   const TransferOptions& options) {
  kernel_ = name;
  transfer_ = options;
  return *this;
}

template <int D>
SimulationBuilder<D>& SimulationBuilder<D>::gravity(const Vec<D>& g) {
  gravity_ = g;
  return *this;
}

template <int D>
int SimulationBuilder<D>::material(std::unique_ptr<Material<D>> model) {
  materials_.push_back(std::move(model));
  return static_cast<int>(materials_.size()) - 1;
}

template <int D>
SimulationBuilder<D>& SimulationBuilder<D>::body(BodySetup<D> body) {
  bodies_.push_back(std::move(body));
  return *this;
}

template <int D>
SimulationBuilder<D>& SimulationBuilder<D>::contact(std::unique_ptr<ContactModel<D>> model) {
  contact_ = std::move(model);
  return *this;
}

template <int D>
SimulationBuilder<D>& SimulationBuilder<D>::hook(std::unique_ptr<StepHook<D>> hook) {
  hooks_.push_back(std::move(hook));
  return *this;
}

template <int D>
SimulationBuilder<D>& SimulationBuilder<D>::select_points(PointSelection<D> select) {
  select_ = std::move(select);
  return *this;
}

namespace {

//! Where a body's points are and what each stands for: the samples of a membrane (volume =
//! length or area × thickness, IJNME §3: m = ρ Δs t) or the filled sub-cells of a region, in
//! the order the body is built. A membrane's are held; a region's fill is held when `hold` (a
//! whole build), else walked anew each time (a distributed run's rank, which then holds no
//! point of the whole body).
template <int D>
class Placement {
 public:
  Placement(const BodySetup<D>& b, const Region<D>* region, const Vec<D>& lower,
            const Vec<D>& upper, double cell, Kinematics kinematics, bool hold)
      : ppc_(b.points_per_cell),
        region_(b.membrane ? nullptr : region),
        lower_(lower),
        upper_(upper),
        cell_(cell),
        kinematics_(kinematics) {
    const bool axisymmetric = kinematics == Kinematics::axisymmetric;
    if (b.membrane) {
      for (std::size_t i = 0; i < b.membrane->points.size(); ++i) {
        Vec<D> x = b.membrane->points[i];
        const double ds = b.membrane->measure[i], v = ds * b.thickness;
        // On the axis the hoop terms v_r / r and σθθ / r are singular and the ring a point
        // stands for has no area: a point closer to it than a quarter spacing sits there.
        if (axisymmetric) x[0] = std::max(x[0], 0.25 * ds);
        held_.emplace_back(x, axisymmetric ? 2.0 * std::numbers::pi * x[0] * v : v);
      }
    } else if (region_ && hold) {
      for_each_fill_point<D>(*region_, lower, upper, cell, ppc_, [&](const Vec<D>& x) {
        held_.emplace_back(x, point_volume<D>(cell, ppc_, kinematics, x));
      });
    }
    holding_ = b.membrane || hold;
    for_each([&](const Vec<D>& x, double volume) {
      if (count_++ == 0) first_ = x;
      volume_ += volume;
    });
  }
  //! visit(x, volume) for each point in turn.
  template <class Visit>
  void for_each(Visit&& visit) const {
    if (holding_) {
      for (const auto& [x, volume] : held_) visit(x, volume);
    } else if (region_) {
      for_each_fill_point<D>(*region_, lower_, upper_, cell_, ppc_, [&](const Vec<D>& x) {
        visit(x, point_volume<D>(cell_, ppc_, kinematics_, x));
      });
    }
  }
  long count() const { return count_; }
  //! Σ of the points' volumes, in order.
  double volume() const { return volume_; }
  const Vec<D>& first() const { return holding_ ? held_.front().first : first_; }
  //! A membrane's points, which the set-up may put back on a face they lie a round-off beyond.
  std::vector<std::pair<Vec<D>, double>>& held() { return held_; }

 private:
  int ppc_;
  const Region<D>* region_;
  Vec<D> lower_, upper_;
  double cell_;
  Kinematics kinematics_;
  bool holding_ = false;
  std::vector<std::pair<Vec<D>, double>> held_;
  long count_ = 0;
  double volume_ = 0.0;
  Vec<D> first_ = Vec<D>::Zero();
};

//! Whether part of a region lies outside the grid box (where fills place no points) other than
//! beyond a slip face (a symmetry plane: a quarter model's region is cut there on purpose): a
//! probe of its bounding box at the fill's spacing, or coarser, at most about 10^5 samples.
template <int D>
bool reaches_outside(const Region<D>& region, const Vec<D>& lower, const Vec<D>& upper,
                     const FaceConditions<D>& faces, double spacing) {
  const Box<D> box = region.bounds();
  bool beyond = false;
  for (int d = 0; d < D; ++d) beyond = beyond || box.lower[d] < lower[d] || box.upper[d] > upper[d];
  if (!beyond) return false;
  double volume = 1.0;
  for (int d = 0; d < D; ++d) volume *= box.upper[d] - box.lower[d];
  const double step = std::max(spacing, std::pow(volume / 1e5, 1.0 / D));
  IVec<D> count;
  long total = 1;
  for (int d = 0; d < D; ++d) {
    count[d] = std::max(1, static_cast<int>(std::ceil((box.upper[d] - box.lower[d]) / step)));
    total *= count[d];
  }
  for (long k = 0; k < total; ++k) {
    Vec<D> x;
    long rest = k;
    bool outside = false;
    for (int d = 0; d < D; ++d) {
      x[d] = box.lower[d] + (static_cast<double>(rest % count[d]) + 0.5) * step;
      rest /= count[d];
      outside = outside || (x[d] < lower[d] && faces[2 * d] != FaceCondition::slip) ||
                (x[d] > upper[d] && faces[2 * d + 1] != FaceCondition::slip);
    }
    if (outside && region.contains(x)) return true;
  }
  return false;
}

//! The grid's wall and symmetry faces as planes.
template <int D>
std::vector<MirrorPlane> mirror_planes(const Vec<D>& lower, const Vec<D>& upper,
                                       const FaceConditions<D>& faces) {
  std::vector<MirrorPlane> planes;
  for (int f = 0; f < 2 * D; ++f)
    if (faces[f] != FaceCondition::free)
      planes.push_back({f / 2, f % 2 == 0 ? lower[f / 2] : upper[f / 2]});
  return planes;
}

//! Add body `b`'s points as placed (`placement`) to `points`: those `kept` flags, each numbered
//! by its index in the body in `built_index`, or all of them when `kept` is null. What belongs
//! to the whole body (its mass and centre, a total_mass's density, the velocity of its first
//! point, point indices) comes from all its placed points.
template <int D>
void add_body(const BodySetup<D>& b, const Material<D>& material, const Placement<D>& placement,
              const std::vector<char>* kept, std::shared_ptr<FrameEstimator<D>> frames,
              Column<double> built_index, Particles<D>& points) {
  const long count = placement.count();
  points.bodies.push_back(
      {b.name, b.material, Vec<D>::Zero(), points.size(), points.size(), std::move(frames)});
  double density = b.density.value_or(material.density());
  if (b.total_mass) density = *b.total_mass / placement.volume();
  // Point masses given explicitly (an end mass on a string) keep their point's volume; the
  // last given for a point holds.
  std::map<long, double> explicit_mass;
  for (const auto& [point, point_mass] : b.point_masses) explicit_mass[point] = point_mass;
  // One walk: the kept points, their indices in the body (all of them without a selection),
  // and the whole body's mass and first moment in the order it is built.
  std::vector<long> kept_index;
  double body_mass = 0.0;
  Vec<D> first_moment = Vec<D>::Zero();
  auto given = explicit_mass.begin();
  long k = 0;
  placement.for_each([&](const Vec<D>& x, double volume) {
    if (!kept || (*kept)[k]) {
      points.add(x, b.velocity, density * volume, density);
      if (kept) {
        points[built_index].back() = static_cast<double>(k);
        kept_index.push_back(k);
      }
    }
    double m = density * volume;
    if (given != explicit_mass.end() && given->first == k) m = (given++)->second;
    body_mass += m;
    first_moment += m * x;
    ++k;
  });
  auto& body = points.bodies.back();
  body.built = count;
  body.cut_at = b.cut_at;
  // The first kept point whose index in the body is i or more, and the kept point of index
  // i (−1 when another process keeps it).
  auto from = [&](long i) {
    if (!kept) return body.begin + std::min(i, count);
    return body.begin +
           static_cast<long>(std::lower_bound(kept_index.begin(), kept_index.end(), i) -
                             kept_index.begin());
  };
  auto at = [&](long i) {
    const long p = from(i);
    return p < body.end && (!kept || kept_index[p - body.begin] == i) ? p : -1;
  };
  InitialState<D> state;
  state.internal_energy = b.internal_energy;
  material.initialise(points, body.begin, body.end, state);
  state.strain = b.initial_strain.value_or(Sym<D>::Zero());
  state.stress = b.initial_stress;
  const long last = b.initial_points.second < 0 ? count - 1 : b.initial_points.second;
  if (last < count)
    material.initialise(points, from(b.initial_points.first), from(last + 1), state);
  for (const auto& [point, point_mass] : explicit_mass)
    if (const long p = at(point); p >= 0) {
      points.mass[p] = point_mass;
      points.density[p] = point_mass / points.volume[p];
    }
  body.applied_acceleration = b.external_force / body_mass;
  const Vec<D> center = b.center.value_or(first_moment / body_mass);
  auto swirl = [&](const Vec<D>& x) -> Vec<D> {  // ω × (x − c) + G (x − c)
    Vec3 r = Vec3::Zero();
    r.template head<D>() = x - center;
    return b.angular_velocity.cross(r).template head<D>() +
           b.velocity_gradient * r.template head<D>();
  };
  for (long p = body.begin; p < body.end; ++p) points.velocity[p] += swirl(points.position[p]);
  body.start_velocity = b.velocity + swirl(placement.first());
  for (const auto& [point, velocity] : b.point_velocities) {
    if (point == 0) body.start_velocity = velocity;
    if (const long p = at(point); p >= 0) points.velocity[p] = velocity;
  }
}

}  // namespace

template <int D>
std::unique_ptr<Simulation<D>> SimulationBuilder<D>::build() {
  std::vector<SetupProblem> problems;
  const KernelChoice<D>* kernel = nullptr;
  for (const auto& k : kernel_choices<D>())
    if (k.name == kernel_) kernel = &k;
  if (!kernel) problems.push_back({-1, "kernel", "no kernel named \"" + kernel_ + "\""});
  if (kernel && transfer_.update == VelocityUpdate::apic && !kernel->offers_apic)
    problems.push_back({-1, "velocity_update", "APIC is not offered with kernel " + kernel_});
  if (bodies_.empty()) problems.push_back({-1, "body", "no body"});

  // Built in part (a distributed run's rank), the simulation stores only its window of the
  // grid, which it takes once its patch is known.
  Grid<D> grid = select_ ? Grid<D>::without_storage(lower_, upper_, cell_, faces_)
                         : Grid<D>(lower_, upper_, cell_, faces_);
  const std::vector<MirrorPlane> mirrors = mirror_planes<D>(lower_, upper_, faces_);
  // Bodies filling a membrane's inside: their regions, and which membrane each fills.
  std::vector<RegionPtr<D>> inside_regions(bodies_.size());
  std::vector<int> filled_by(bodies_.size(), -1);
  std::vector<std::vector<MirrorPlane>> closing(bodies_.size());  // per membrane
  for (std::size_t index = 0; index < bodies_.size(); ++index) {
    const BodySetup<D>& b = bodies_[index];
    if (b.inside.empty()) continue;
    const int i = static_cast<int>(index);
    const auto it = std::find_if(bodies_.begin(), bodies_.end(),
                                 [&](const auto& m) { return m.name == b.inside && m.membrane; });
    if (it == bodies_.end()) {
      problems.push_back(
          {i, "region.inside", "body '" + b.name + "': no membrane body named '" + b.inside + "'"});
      continue;
    }
    const MembraneGeometry<D>& m = *it->membrane;
    auto enclosure = std::make_shared<const Enclosure<D>>(
        m.points, 0, static_cast<long>(m.points.size()), m.connectivity, mirrors,
        std::max(m.longest_gap, 1e-9 * cell_));
    if (!enclosure->problem().empty()) {
      problems.push_back({i, "region.inside",
                          "body '" + b.name + "' cannot fill membrane '" + b.inside +
                              "': " + enclosure->problem()});
      continue;
    }
    closing[it - bodies_.begin()] = enclosure->closing_planes();
    const double gap = b.gap >= 0.0 ? b.gap : 0.5 / b.points_per_cell;
    inside_regions[index] = make_enclosed_region<D>(std::move(enclosure), gap * cell_);
    filled_by[it - bodies_.begin()] = i;
  }
  std::vector<Placement<D>> placed;
  long total = 0;
  for (std::size_t index = 0; index < bodies_.size(); ++index) {
    const BodySetup<D>& b = bodies_[index];
    placed.emplace_back(b, inside_regions[index] ? inside_regions[index].get() : b.region.get(),
                        lower_, upper_, cell_, settings_.kinematics, !select_);
    total += placed[index].count();
    if (!b.membrane && b.region && placed[index].count() > 0 &&
        reaches_outside(*b.region, lower_, upper_, faces_, cell_ / b.points_per_cell))
      log_warning("body '" + b.name +
                  "': part of its region lies outside the grid; that part holds no points");
  }

  // Every body's checks first (they put membrane points a round-off beyond a face back on
  // it), then which points this process keeps, then the points.
  std::vector<std::shared_ptr<FrameEstimator<D>>> frames(bodies_.size());
  for (std::size_t index = 0; index < bodies_.size(); ++index) {
    const BodySetup<D>& b = bodies_[index];
    const int i = static_cast<int>(index);
    if (b.material < 0 || b.material >= static_cast<int>(materials_.size())) {
      problems.push_back({i, "material", "body '" + b.name + "': no such material"});
      continue;
    }
    const Material<D>& material = *materials_[b.material];
    if (material.is_membrane() != b.membrane.has_value()) {
      problems.push_back({i, "material",
                          "body '" + b.name + "': " +
                              (b.membrane ? "a membrane body needs a membrane material"
                                          : "a membrane material needs a membrane body")});
      continue;
    }
    if (kernel && kernel->one_particle_size && b.points_per_cell != bodies_.front().points_per_cell)
      problems.push_back({i, "points_per_cell",
                          "kernel " + kernel_ +
                              " has one particle size (h / points_per_cell): "
                              "every body must use the same points_per_cell"});
    const long count = placed[index].count();
    if (count == 0) {
      if (!b.inside.empty() && !inside_regions[index]) continue;  // reported above
      problems.push_back(
          {i, "region", "body '" + b.name + "': the region holds no point inside the grid"});
      continue;
    }
    bool outside = false;
    for (auto& [x, v] : placed[index].held())  // a curve sampled onto a face may end beyond it
      outside = outside || !(grid.contains(x) || grid.return_to_face(x));
    if (outside) {
      problems.push_back(
          {i, "membrane", "body '" + b.name + "': membrane points lie outside the grid"});
      continue;
    }
    auto check_index = [&](long point, const char* key) {
      if (point >= count)
        problems.push_back({i, key,
                            "body '" + b.name + "': no point " + std::to_string(point) +
                                " (it has " + std::to_string(count) + ")"});
    };
    for (const auto& entry : b.point_masses) check_index(entry.first, "point_masses");
    for (const auto& entry : b.point_velocities) check_index(entry.first, "point_velocities");
    check_index(b.initial_points.second < 0 ? count - 1 : b.initial_points.second,
                "initial_strain.points");
    if (b.membrane) {
      FrameSetup<D> setup;
      setup.connectivity = b.membrane->connectivity;
      setup.grid_origin = lower_;
      setup.cell = cell_;
      setup.mirrors = mirrors;
      if (filled_by[index] >= 0) {
        // Of the filled body's points, those the first normals look at.
        std::vector<Vec<D>> membrane;
        for (const auto& entry : placed[index].held()) membrane.push_back(entry.first);
        const WithinACell<D> near(membrane, 0, static_cast<long>(membrane.size()), cell_);
        placed[filled_by[index]].for_each([&](const Vec<D>& y, double) {
          if (near(y)) setup.orientation.inside.push_back(y);
        });
      }
      setup.orientation.rule =
          b.orientation.value_or(filled_by[index] >= 0 ? NormalOrientation::away_from_inside
                                                       : NormalOrientation::propagate);
      for (const auto& e : frame_estimators<D>())
        if (e.name == b.frames) frames[index] = e.make(setup);
      if (!frames[index])
        problems.push_back({i, "frames", "no frame estimator named \"" + b.frames + "\""});
    }
  }
  if (!problems.empty()) throw BuildError(problems);

  std::vector<std::vector<char>> keep;
  if (select_) {
    std::vector<PlacedBody<D>> all;
    for (std::size_t index = 0; index < bodies_.size(); ++index)
      all.push_back({bodies_[index].name, placed[index].count(),
                     [&placement = placed[index]](const std::function<void(const Vec<D>&)>& visit) {
                       placement.for_each([&](const Vec<D>& x, double) { visit(x); });
                     }});
    keep = select_(grid, all);
    bool fits = keep.size() == bodies_.size();
    for (std::size_t index = 0; fits && index < keep.size(); ++index)
      fits = static_cast<long>(keep[index].size()) == placed[index].count();
    if (!fits) throw std::logic_error("a point selection must flag every placed point");
    total = 0;
    for (const auto& flags : keep) total += std::count(flags.begin(), flags.end(), 1);
  }
  Particles<D> points;
  for (auto& material : materials_) material->declare_columns(points);
  Column<double> built_index;
  if (select_)
    built_index = points.template declare<double>({column_names::body_index, "1", true, false});
  points.reserve(total);  // every column once, at its final size
  for (std::size_t index = 0; index < bodies_.size(); ++index)
    add_body<D>(bodies_[index], *materials_[bodies_[index].material], placed[index],
                select_ ? &keep[index] : nullptr, frames[index], built_index, points);

  TransferOptions options = transfer_;
  options.kinematics = settings_.kinematics;
  auto simulation = std::make_unique<Simulation<D>>(
      settings_, std::move(grid), std::move(points), std::move(materials_),
      kernel->make(options, bodies_.front().points_per_cell), gravity_);
  simulation->set_contact(std::move(contact_));
  for (auto& hook : hooks_) simulation->add_hook(std::move(hook));
  for (std::size_t index = 0; index < bodies_.size(); ++index) {
    if (filled_by[index] < 0) continue;
    const BodySetup<D>& m = bodies_[index];
    simulation->add_enclosed({static_cast<int>(index), filled_by[index], m.membrane->connectivity,
                              closing[index], std::max(m.membrane->longest_gap, 1e-9 * cell_),
                              m.thickness});
  }
  return simulation;
}

template class SimulationBuilder<2>;
template class SimulationBuilder<3>;
template double point_volume<2>(double, int, Kinematics, const Vec<2>&);
template double point_volume<3>(double, int, Kinematics, const Vec<3>&);

}  // namespace pellicle
