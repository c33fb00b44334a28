#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "pellicle/core/input_file.hpp"
#include "pellicle/geometry/region_factory.hpp"
#include "pellicle/io/case.hpp"
#include "pellicle/io/case_source.hpp"
#include "pellicle/io/problem_size.hpp"
#include "pellicle/io/toml_parameters.hpp"
#include "pellicle/mpm/boundary/boundary_condition.hpp"
#include "pellicle/normals/frame_estimator.hpp"

namespace pellicle {

OutputSettings read_output_settings(TomlParameters& o, const std::string& name, double end_time) {
  OutputSettings out;
  out.directory = o.text_or("directory", "results/" + name);
  out.history_interval =
      o.number_or("history_interval", end_time / 1000.0, NumberRange::non_negative());
  out.snapshot_interval =
      o.number_or("snapshot_interval", end_time / 20.0, NumberRange::non_negative());
  return out;
}

SourceLocation location_of(const toml::source_region& src, const std::string& file) {
  return {src.path ? *src.path : file, static_cast<int>(src.begin.line),
          static_cast<int>(src.begin.column)};
}

namespace {

toml::table parse(const std::string& text, const std::string& file) {
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw InputError(location_of(e.source(), file), "", std::string(e.description()));
  }
}

//! Split "body[1].velocity" into {"body", 1}, {"velocity", -1}.
struct PathPart {
  std::string key;
  long index = -1;
};
std::vector<PathPart> split_path(const std::string& path, const std::string& setting) {
  std::vector<PathPart> parts;
  std::stringstream in(path);
  std::string piece;
  const SourceLocation where{"--set " + setting, 0, 0};
  while (std::getline(in, piece, '.')) {
    PathPart part;
    const auto bracket = piece.find('[');
    part.key = piece.substr(0, bracket);
    if (bracket != std::string::npos) {
      const auto close = piece.find(']', bracket);
      try {
        if (close != piece.size() - 1) throw std::invalid_argument("bracket");
        part.index = std::stol(piece.substr(bracket + 1, close - bracket - 1));
      } catch (const std::exception&) {
        throw InputError(where, path, "expected an index like body[0], found \"" + piece + "\"");
      }
    }
    if (part.key.empty()) throw InputError(where, path, "expected a dotted key path");
    parts.push_back(part);
  }
  if (parts.empty()) throw InputError(where, path, "expected a dotted key path");
  return parts;
}

void apply_override(toml::table& root, const std::string& setting) {
  const auto eq = setting.find('=');
  const SourceLocation where{"--set " + setting, 0, 0};
  if (eq == std::string::npos || eq == 0)
    throw InputError(where, "", "expected key=value, e.g. --set solver.end_time=0.5");
  const std::string path = setting.substr(0, eq), value = setting.substr(eq + 1);
  const auto parts = split_path(path, setting);

  // The value is read as TOML (numbers, arrays, booleans, quoted strings); anything else is
  // taken as a bare string, so `--set solver.scheme=usl` works without quotes.
  toml::table holder;
  try {
    holder = toml::parse("value = " + value, "--set " + setting);
  } catch (const toml::parse_error&) {
    // As a quoted string, parsed from the same source name, so problems with it name the
    // --set argument.
    std::string quoted = "\"";
    for (const char ch : value) {
      if (ch == '"' || ch == '\\') quoted += '\\';
      quoted += ch;
    }
    quoted += '"';
    try {
      holder = toml::parse("value = " + quoted, "--set " + setting);
    } catch (const toml::parse_error&) {
      throw InputError(where, path, "expected a TOML value or plain text, found \"" + value + "\"");
    }
  }

  toml::table* table = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* next = table->get(parts[i].key);
    if (!next) next = &table->insert(parts[i].key, toml::table{}).first->second;
    if (parts[i].index >= 0) {
      toml::array* array = next->as_array();
      if (!array || parts[i].index >= static_cast<long>(array->size()))
        throw InputError(where, path,
                         "no element " + std::to_string(parts[i].index) + " in " + parts[i].key);
      next = array->get(parts[i].index);
    }
    table = next->as_table();
    if (!table) throw InputError(where, path, parts[i].key + " is not a table");
  }
  if (parts.back().index >= 0)
    throw InputError(where, path, "an override replaces a whole key; drop the index");
  table->insert_or_assign(parts.back().key, std::move(*holder.get("value")));
}

}  // namespace

std::shared_ptr<CaseSource> case_source_from_text(const std::string& text, const std::string& name,
                                                  const std::vector<std::string>& overrides) {
  auto source = std::make_shared<CaseSource>();
  source->file = name;
  source->text = text;
  source->root = parse(source->text, source->file);
  for (const auto& o : overrides) {
    apply_override(source->root, o);
    source->text += "\n# --set " + o;  // overrides are part of what was run (case hash)
  }
  return source;
}

std::shared_ptr<CaseSource> load_case_source(const std::string& path,
                                             const std::vector<std::string>& overrides) {
  if (path.empty()) return case_source_from_text(default_case_text(), "<default case>", overrides);
  constexpr std::uintmax_t kLargestCase = 16u << 20;  // bytes; a case is a page of text
  return case_source_from_text(read_input_file(path, "", "case file", kLargestCase), path,
                               overrides);
}

int case_dimension(const CaseSource& source) {
  const toml::node* lower = source.root.at_path("grid.lower").node();
  const toml::array* array = lower ? lower->as_array() : nullptr;
  if (!array || (array->size() != 2 && array->size() != 3)) {
    const toml::node* where = lower ? lower : source.root.get("grid");
    SourceLocation loc{source.file, 1, 1};
    if (where) loc = location_of(where->source(), source.file);
    throw InputError(loc, "grid.lower",
                     "expected an array of 2 (2D) or 3 (3D) numbers, found " +
                         (lower ? describe_node(*lower) : std::string("nothing (required)")));
  }
  return static_cast<int>(array->size());
}

const std::string& case_text(const CaseSource& source) {
  return source.text;
}

namespace {

template <int D>
Sym<D> read_tensor(ParameterReader& in) {
  Sym<D> s = Sym<D>::Zero();
  const char* names2[] = {"xx", "yy", "zz", "xy"};
  const char* names3[] = {"xx", "yy", "zz", "yz", "xz", "xy"};
  for (int k = 0; k < kSymComponents<D>; ++k)
    s[k] = in.number_or(D == 2 ? names2[k] : names3[k], 0.0, NumberRange::any());
  return s;
}

const char* face_names[] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};

template <int D>
void read_grid(TomlParameters& root, Case<D>& c) {
  auto grid = root.sub_table("grid", true);
  c.lower = read_vector<D>(*grid, "lower");
  c.upper = read_vector<D>(*grid, "upper");
  c.cell = grid->number("cell", NumberRange::positive());
  c.cell_where = grid->location("cell");
  for (int d = 0; d < D; ++d) {
    const double span = c.upper[d] - c.lower[d];
    if (span <= 0.0) {
      grid->fail("upper", "expected every component above grid.lower");
      break;
    }
    const double cells = span / c.cell;
    constexpr double kMostCells = 1e7;  // per axis; the memory check bounds the product
    if (cells > kMostCells) {
      std::ostringstream msg;
      msg << "expected at most " << kMostCells << " cells on an axis, found " << cells
          << " on axis " << d;
      grid->fail("cell", msg.str());
      break;
    }
    if (std::abs(cells - std::round(cells)) > 1e-6 * std::max(1.0, cells)) {
      std::ostringstream msg;
      msg << "expected (upper − lower)/cell to be a whole number of cells on every axis, found "
          << cells << " on axis " << d;
      grid->fail("cell", msg.str());
      break;
    }
  }

  if constexpr (D == 2) {
    const std::string k = grid->choice(
        "kinematics", {"plane-strain", "plane-stress", "axisymmetric"}, "plane-strain");
    c.settings.kinematics = k == "plane-stress"   ? Kinematics::plane_stress
                            : k == "axisymmetric" ? Kinematics::axisymmetric
                                                  : Kinematics::plane_strain;
  } else {
    grid->choice("kinematics", {"solid"}, "solid");
    c.settings.kinematics = Kinematics::solid;
  }
  c.transfer.kinematics = c.settings.kinematics;

  auto faces = grid->sub_table("boundary", false);
  for (int f = 0; f < 2 * D; ++f) {
    const std::string v = faces->choice(face_names[f], {"fixed", "slip", "free"}, "fixed");
    c.faces[f] = v == "slip"   ? FaceCondition::slip
                 : v == "free" ? FaceCondition::free
                               : FaceCondition::fixed;
  }
  if (c.settings.kinematics == Kinematics::axisymmetric) {
    if (c.lower[0] < 0.0) grid->fail("lower", "expected radius lower[0] >= 0 in axisymmetry");
    if (c.lower[0] == 0.0) {
      if (faces->has("x_min") && c.faces[0] != FaceCondition::slip)
        faces->fail("x_min", "expected \"slip\": x_min is the symmetry axis r = 0");
      c.faces[0] = FaceCondition::slip;
    }
  }
}

template <int D>
void read_solver(TomlParameters& root, Case<D>& c) {
  auto s = root.sub_table("solver", true);
  const std::string scheme = s->choice("scheme", {"musl", "usl", "usf"}, "musl");
  c.settings.scheme = scheme == "usl"   ? UpdateScheme::usl
                      : scheme == "usf" ? UpdateScheme::usf
                                        : UpdateScheme::musl;
  const std::string update = s->choice("velocity_update", {"flip", "pic", "blend", "apic"}, "flip");
  c.transfer.update = update == "pic"     ? VelocityUpdate::pic
                      : update == "blend" ? VelocityUpdate::blend
                      : update == "apic"  ? VelocityUpdate::apic
                                          : VelocityUpdate::flip;
  if (s->has("flip_fraction") && update != "blend")
    s->fail("flip_fraction", "only used with velocity_update = \"blend\"");
  c.transfer.flip_fraction = s->number_or("flip_fraction", 0.99, NumberRange::closed(0.0, 1.0));

  std::vector<std::string> kernels;
  for (const auto& k : kernel_choices<D>()) kernels.push_back(k.name);
  c.kernel = s->choice("kernel", kernels, "linear");
  const auto& kernel = kernel_choices<D>();
  const auto chosen =
      std::find_if(kernel.begin(), kernel.end(), [&](const auto& k) { return k.name == c.kernel; });
  if (c.transfer.update == VelocityUpdate::apic && chosen != kernel.end() && !chosen->offers_apic)
    s->fail("velocity_update",
            "APIC is not offered with the linear kernel: it goes unstable at free surfaces (the "
            "two-disk test); use kernel = \"quadratic-bspline\", \"cubic-bspline\" or \"ugimp\"");

  c.settings.end_time = s->number("end_time", NumberRange::positive());
  if (s->has("dt") && s->has("cfl")) s->fail("cfl", "give either dt (fixed) or cfl, not both");
  c.settings.fixed_dt = s->number_or("dt", 0.0, NumberRange::positive());
  c.settings.cfl_fraction = s->number_or("cfl", 0.5, NumberRange::open_closed(0.0, 1.0));
  if (c.settings.fixed_dt > 0.0) c.settings.cfl_fraction = 0.0;
  c.settings.cfl_limit = s->number_or("cfl_limit", 1.0, NumberRange::positive());
  c.settings.max_steps = s->integer_or("max_steps", c.settings.max_steps, 1, 1000000000000L);
  c.settings.rebalance = s->number_or("rebalance", c.settings.rebalance, NumberRange::positive());
  c.time_step_key = s->has("dt") ? "solver.dt" : "solver.cfl";
  c.time_step_where = s->location(s->has("dt") ? "dt" : "cfl");
  c.gravity = read_vector_or<D>(*s, "gravity", Vec<D>::Zero());
}

template <int D>
void read_output(TomlParameters& root, Case<D>& c) {
  auto o = root.sub_table("output", false);
  c.output = read_output_settings(*o, c.name, c.settings.end_time);
  c.output.grid_snapshots = o->flag_or("grid_snapshots", false);
  c.output.checkpoint_interval =
      o->number_or("checkpoint_interval", 0.0, NumberRange::non_negative());
}

template <int D>
void read_materials(TomlParameters& root, Case<D>& c) {
  std::vector<std::string> models;
  for (const auto& m : material_models<D>()) models.push_back(m.name);
  for (auto& t : root.sub_tables("material")) {
    const std::string name = read_name(*t, "name");
    if (std::count(c.material_names.begin(), c.material_names.end(), name))
      t->fail("name", "expected a unique material name, found \"" + name + "\" again");
    const std::string model = t->choice("model", models);
    std::unique_ptr<Material<D>> made;
    for (const auto& m : material_models<D>())
      if (m.name == model) made = m.make(*t, c.settings.kinematics);
    if (!made) t->ignore_rest();
    c.material_names.push_back(name);
    c.materials.push_back(std::move(made));
  }
}

//! A body is either a solid filling a region or a membrane on a curve or surface; its
//! material must be of the same kind.
template <int D>
void read_membrane_or_region(TomlParameters& t, Case<D>& c, BodySpec<D>& b) {
  const bool membrane = t.has("membrane");
  if (membrane && t.has("region")) t.fail("membrane", "give either region (solid) or membrane");
  if (membrane) {
    auto m = t.sub_table("membrane", true);
    const std::string base = std::filesystem::path(c.file).parent_path().string();
    b.membrane =
        make_membrane_geometry<D>(*m, c.cell, base.empty() ? "." : base, most_points_in_memory());
    b.thickness = m->number("thickness", NumberRange::positive());
    std::vector<std::string> estimators;
    for (const auto& e : frame_estimators<D>()) estimators.push_back(e.name);
    b.frames = m->choice("frames", estimators, "connectivity");
    if (m->has("orientation")) {
      const std::string side =
          m->choice("orientation", {"propagate", "outward", "away-from-inside"});
      b.orientation = side == "outward"            ? NormalOrientation::outward
                      : side == "away-from-inside" ? NormalOrientation::away_from_inside
                                                   : NormalOrientation::propagate;
    }
  } else {
    auto region = t.sub_table("region", true);
    if (region->has("inside")) {  // the inside of a membrane body, checked when it is built
      b.inside = region->text("inside");
      b.gap = region->number_or("gap", -1.0, NumberRange::non_negative());
      if (b.inside.empty()) region->fail("inside", "expected the name of a membrane body");
    } else {
      b.region = make_region<D>(*region);
    }
  }
  const Material<D>* material =
      b.material < static_cast<int>(c.materials.size()) ? c.materials[b.material].get() : nullptr;
  if (material && material->is_membrane() != membrane)
    t.fail("material", membrane
                           ? "expected a material with model = \"membrane\" for a membrane body"
                           : "expected a solid material: model \"membrane\" needs a membrane body");
}

template <int D>
void read_bodies(TomlParameters& root, Case<D>& c) {
  std::set<std::string> names;
  for (auto& t : root.sub_tables("body")) {
    BodySpec<D> b;
    b.where = t->location();
    b.name = read_name(*t, "name");
    if (!names.insert(b.name).second)
      t->fail("name", "expected a unique body name, found \"" + b.name + "\" again");
    const std::string material = t->text("material");
    const auto it = std::find(c.material_names.begin(), c.material_names.end(), material);
    if (it == c.material_names.end() && !material.empty())
      t->fail("material", "expected the name of a [[material]], found \"" + material + "\"");
    b.material = it == c.material_names.end() ? 0 : static_cast<int>(it - c.material_names.begin());
    read_membrane_or_region(*t, c, b);
    if (!b.membrane)
      b.points_per_cell = static_cast<int>(t->integer_or("points_per_cell", 2, 1, 16));
    b.velocity = read_vector_or<D>(*t, "velocity", Vec<D>::Zero());
    if constexpr (D == 2) {
      b.angular_velocity.z() = t->number_or("angular_velocity", 0.0, NumberRange::any());
    } else {
      b.angular_velocity = read_vector_or<3>(*t, "angular_velocity", Vec3::Zero());
    }
    if (t->has("velocity_gradient")) {
      const auto rows = t->number_lists("velocity_gradient", D);
      if (static_cast<int>(rows.size()) != D)
        t->fail("velocity_gradient",
                "expected " + std::to_string(D) + " rows of " + std::to_string(D) + " numbers");
      for (int i = 0; i < std::min<int>(D, rows.size()); ++i)
        for (int j = 0; j < D; ++j) b.velocity_gradient(i, j) = rows[i][j];
    }
    if (t->has("center")) b.center = read_vector<D>(*t, "center");
    b.external_force = read_vector_or<D>(*t, "external_force", Vec<D>::Zero());
    if (t->has("point_masses")) {
      for (const auto& entry : t->number_lists("point_masses", 2)) {
        if (entry[0] < 0 || entry[0] != std::floor(entry[0]) || !(entry[1] > 0))
          t->fail("point_masses",
                  "expected [[index, mass], …] with whole indices >= 0 and masses > 0");
        else
          b.point_masses.emplace_back(static_cast<long>(entry[0]), entry[1]);
      }
    }
    if (t->has("point_velocities")) {
      for (const auto& entry : t->number_lists("point_velocities", D + 1)) {
        if (entry[0] < 0 || entry[0] != std::floor(entry[0])) {
          t->fail("point_velocities", "expected [[index, v_x, v_y" +
                                          std::string(D == 3 ? ", v_z" : "") +
                                          "], …] with whole indices >= 0");
          continue;
        }
        Vec<D> v;
        for (int d = 0; d < D; ++d) v[d] = entry[d + 1];
        b.point_velocities.emplace_back(static_cast<long>(entry[0]), v);
      }
    }
    if (t->has("density")) b.density = t->number("density", NumberRange::positive());
    if (t->has("total_mass")) {
      if (t->has("density")) t->fail("total_mass", "give either density or total_mass, not both");
      b.total_mass = t->number("total_mass", NumberRange::positive());
    }
    if (t->has("cut_at")) {
      b.cut_at = t->number("cut_at", NumberRange::non_negative());
      if (!b.membrane) t->fail("cut_at", "only membrane bodies (strings, tethers) can be cut");
    }
    if (t->has("internal_energy")) {
      b.internal_energy = t->number("internal_energy", NumberRange::non_negative());
      const bool fluid = b.material < static_cast<int>(c.materials.size()) &&
                         c.materials[b.material] && c.materials[b.material]->is_fluid();
      if (!fluid)
        t->fail("internal_energy",
                "only fluid bodies (model \"gas\", \"barotropic-liquid\", \"tait-liquid\") "
                "carry an internal energy");
    }
    if (t->has("initial_stress") && b.membrane)
      t->fail("initial_stress", "membranes take initial_strain (their stress follows from it)");
    if (t->has("initial_stress") && t->has("initial_strain"))
      t->fail("initial_strain", "give either initial_stress or initial_strain, not both");
    for (const char* key : {"initial_stress", "initial_strain"}) {
      if (!t->has(key)) continue;
      auto table = t->sub_table(key, true);
      (std::string(key) == "initial_stress" ? b.initial_stress : b.initial_strain) =
          read_tensor<D>(*table);
      if (table->has("points")) {
        const auto range = table->numbers("points", 2, NumberRange::non_negative());
        if (range[1] < range[0] || range[0] != std::floor(range[0]) ||
            range[1] != std::floor(range[1]))
          table->fail("points", "expected [first, last]: whole point indices, first <= last");
        b.initial_points = {static_cast<long>(range[0]), static_cast<long>(range[1])};
      }
    }
    c.bodies.push_back(std::move(b));
  }
}

template <int D>
void read_probes(TomlParameters& root, Case<D>& c) {
  if (!root.has("probe")) return;
  for (auto& t : root.sub_tables("probe")) {
    ProbeSpec<D> p;
    p.where = t->location();
    p.name = read_name(*t, "name");
    p.body = t->text("body");
    if (std::none_of(c.bodies.begin(), c.bodies.end(),
                     [&](const auto& b) { return b.name == p.body; }))
      t->fail("body", "expected the name of a [[body]], found \"" + p.body + "\"");
    const std::string q = t->choice("quantity", {"position", "velocity", "angle", "radius"});
    auto index = [&](double v, const char* key) {
      if (v < 0 || v != std::floor(v)) t->fail(key, "expected whole point indices >= 0");
      return static_cast<long>(std::max(0.0, v));
    };
    if (q == "angle") {
      p.quantity = ProbeQuantity::angle;
      const auto ab = t->numbers("points", 2, NumberRange::non_negative());
      p.a = index(ab[0], "points");
      p.b = index(ab[1], "points");
      Vec<D> down = Vec<D>::Zero();
      down[D - 1] = -1.0;
      p.reference = read_vector_or<D>(*t, "reference", down);
      if (p.reference.norm() == 0.0) t->fail("reference", "expected a non-zero vector");
    } else if (q == "radius") {
      p.quantity = ProbeQuantity::radius;
      p.a = p.b = index(t->number("point", NumberRange::non_negative()), "point");
      p.reference = read_vector_or<D>(*t, "center", Vec<D>::Zero());
    } else if (!q.empty()) {
      p.quantity = q == "position" ? ProbeQuantity::position : ProbeQuantity::velocity;
      p.a = p.b = index(t->number("point", NumberRange::non_negative()), "point");
    }
    c.probes.push_back(p);
  }
}

//! [contact]: the single centre-of-mass field (default) or a registered contact model.
template <int D>
void read_contact(TomlParameters& root, Case<D>& c) {
  if (!root.has("contact")) return;
  auto t = root.sub_table("contact", true);
  std::vector<std::string> models{"single-field"};
  for (const auto& m : contact_models<D>()) models.push_back(m.name);
  const std::string model = t->choice("model", models, "single-field");
  std::vector<std::string> names;
  for (const auto& b : c.bodies) names.push_back(b.name);
  for (const auto& m : contact_models<D>())
    if (m.name == model) c.contact = m.make(*t, names);

  if (c.contact && c.settings.scheme == UpdateScheme::usf)
    t->fail("model", "contact models work with solver.scheme = \"musl\" or \"usl\", not \"usf\"");
}

//! [[boundary]]: boundary conditions by registered name (mpm/boundary/registry.cpp).
template <int D>
void read_boundaries(TomlParameters& root, Case<D>& c) {
  if (!root.has("boundary")) return;
  std::vector<std::string> models;
  for (const auto& m : boundary_models<D>()) models.push_back(m.name);
  for (auto& t : root.sub_tables("boundary")) {
    const std::string model = t->choice("model", models);
    bool made = false;
    for (const auto& m : boundary_models<D>())
      if (m.name == model) {
        c.boundaries.push_back(m.make(*t));
        made = true;
      }
    if (!made) t->ignore_rest();
  }
}

}  // namespace

template <int D>
Case<D> read_case(const CaseSource& source) {
  Case<D> c;
  c.file = source.file;
  ProblemList problems{source.file, {}};
  {
    TomlParameters root(source.root, "", problems);
    auto meta = root.sub_table("case", false);
    const std::string stem = source.file == "<default case>"
                                 ? "default"
                                 : std::filesystem::path(source.file).stem().string();
    c.name = read_name_or(*meta, "name", stem);
    c.title = meta->text_or("title", c.name);
    c.source = meta->text_or("source", "");
    read_grid(root, c);
    read_solver(root, c);
    read_output(root, c);
    read_materials(root, c);
    read_bodies(root, c);
    read_contact(root, c);
    read_boundaries(root, c);
    read_probes(root, c);
  }  // unknown keys are reported as the readers go out of scope
  problems.throw_if_any();
  return c;
}

template Case<2> read_case<2>(const CaseSource&);
template Case<3> read_case<3>(const CaseSource&);

}  // namespace pellicle
