#include <algorithm>
#include <filesystem>

#include "pellicle/io/case_source.hpp"
#include "pellicle/io/problem_size.hpp"
#include "pellicle/io/surface_case.hpp"
#include "pellicle/io/toml_parameters.hpp"
#include "pellicle/surface/builder.hpp"

namespace pellicle {

bool is_surface_case(const CaseSource& source) {
  return source.root.contains("surface");
}

int surface_case_dimension(const CaseSource& source) {
  const bool several = source.root.at_path("surface.shapes").is_array();
  const std::string shape = several ? "surface.shapes[0]" : "surface.shape";
  const toml::node* kind = source.root.at_path(shape + ".kind").node();
  const std::string name = kind && kind->is_string() ? kind->as_string()->get() : "";
  const auto listed = [&](const std::vector<std::string>& kinds) {
    return std::find(kinds.begin(), kinds.end(), name) != kinds.end();
  };
  const bool two = listed(surface_shape_kinds<2>()), three = listed(surface_shape_kinds<3>());
  if (two && three) {  // a kind of both dimensions: the length of its points decides
    const toml::node* first = source.root.at_path(shape + ".centers[0]").node();
    if (!first) first = source.root.at_path(shape + ".center").node();
    const toml::array* a = first ? first->as_array() : nullptr;
    return a && a->size() == 2 ? 2 : 3;
  }
  return two ? 2 : 3;  // an unknown kind is reported by the 3D reader
}

namespace {

template <int D>
void read_velocity(TomlParameters& s, SurfaceCase<D>& c) {
  for (auto& v : c.velocity) v = PointFormula("0");
  if (!s.has("velocity")) return;
  const toml::node* node = s.take("velocity");
  const toml::array* list = node->as_array();
  const bool formulas =
      list && list->size() == D &&
      std::all_of(list->begin(), list->end(), [](const toml::node& e) { return e.is_string(); });
  if (!formulas) {
    s.fail("velocity", "expected an array of " + std::to_string(D) + " formulas (strings), found " +
                           describe_node(*node));
    return;
  }
  for (int d = 0; d < D; ++d) {
    try {
      c.velocity[d] = PointFormula(list->get(d)->as_string()->get());
    } catch (const ExpressionError& e) {
      s.fail("velocity", "component " + std::to_string(d + 1) + ", column " +
                             std::to_string(e.column()) + " of the formula: " + e.what());
    }
  }
}

//! `shape = {…}` (one surface, named "surface") or `[[surface.shapes]]` (each with a
//! `name`, default "surface-1", "surface-2", …).
template <int D>
void read_shapes(TomlParameters& s, SurfaceCase<D>& c) {
  std::string base = std::filesystem::path(c.file).parent_path().string();
  if (base.empty()) base = ".";
  const bool several = s.has("shapes");
  if (s.has("shape") && several) {
    s.fail("shapes", "expected either `shape` (one surface) or `shapes` (several), not both");
    s.take("shapes");
  }
  if (!several || s.has("shape")) {
    if (auto shape = s.sub_table("shape", true))
      c.surfaces.push_back({"surface", make_surface_shape<D>(*shape, base)});
    return;
  }
  auto tables = s.sub_tables("shapes");
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const std::string name = tables[k]->text_or("name", "surface-" + std::to_string(k + 1));
    for (const auto& other : c.surfaces)
      if (other.name == name) tables[k]->fail("name", "two surfaces are named '" + name + "'");
    c.surfaces.push_back({name, make_surface_shape<D>(*tables[k], base)});
  }
}

//! `[surface.contact]`: the responses of §3.6 between surfaces and within each.
template <int D>
void read_contact(TomlParameters& s, SurfaceCase<D>& c) {
  auto t = s.sub_table("contact", false);
  ContactOptions& o = c.settings.contact;
  const auto& names = contact_response_names();
  o.between = contact_response_from_name(t->choice("between", names, "none"));
  o.self = contact_response_from_name(t->choice("self", names, "none"));
  o.facing_limit = t->number_or("facing_limit", o.facing_limit, NumberRange::closed(-1.0, 0.0));
  if (!t->has("rules")) return;
  for (auto& rule : t->sub_tables("rules")) {
    ContactRule r;
    r.response = contact_response_from_name(rule->choice("response", names));
    const toml::node* node = rule->take("surfaces");
    const toml::array* list = node ? node->as_array() : nullptr;
    int found[2] = {-1, -1};
    if (list && list->size() == 2)
      for (int e = 0; e < 2; ++e)
        if (const auto* name = list->get(e)->as_string())
          for (std::size_t k = 0; k < c.surfaces.size(); ++k)
            if (c.surfaces[k].name == name->get()) found[e] = static_cast<int>(k);
    if (found[0] < 0 || found[1] < 0) {
      std::string known;
      for (const auto& surface : c.surfaces) known += (known.empty() ? "" : ", ") + surface.name;
      rule->fail("surfaces", "expected two surface names out of: " + known);
      continue;
    }
    r.first = found[0];
    r.second = found[1];
    o.rules.push_back(r);
  }
}

template <int D>
void read_surface(TomlParameters& root, SurfaceCase<D>& c, std::uint64_t& seed) {
  auto s = root.sub_table("surface", true);
  read_shapes(*s, c);
  read_contact(*s, c);
  c.smoothing_length = s->number("smoothing_length", NumberRange::positive());
  c.spacing_where = s->location("smoothing_length");
  auto& m = c.settings.management;
  auto t = s->sub_table("management", false);
  c.settings.manage = t->flag_or("enabled", true);
  m.r_max = t->number_or("r_max", m.r_max, NumberRange::open_closed(0.0, 1.0));
  m.r_min = t->number_or("r_min", m.r_min, NumberRange::open_closed(0.0, 1.0));
  m.curvature_correction = t->flag_or("curvature_correction", true);
  m.curvature_rule =
      t->choice("curvature_rule", {"midway", "tangent-planes"}, "midway") == "tangent-planes"
          ? CurvatureRule::tangent_planes
          : CurvatureRule::midway;
  c.settings.management_interval =
      t->number_or("interval", c.settings.management_interval, NumberRange::closed(0.0, 1.0));
  if (m.r_min >= m.r_max) t->fail("r_min", "expected r_min below r_max");
  const double factor = s->number_or("spacing_factor", kPaperSpacingFactor,
                                     NumberRange::closed(m.r_min, 2.0 * m.r_max));
  c.spacing = factor * c.smoothing_length;
  seed = static_cast<std::uint64_t>(s->integer_or("seed", 1, 0, 1L << 40));
  c.settings.frames.weight_exponent = s->number_or(
      "normal_weight_exponent", c.settings.frames.weight_exponent, NumberRange::positive());
  c.settings.gfdm.weight_exponent = s->number_or(
      "stencil_weight_exponent", c.settings.gfdm.weight_exponent, NumberRange::positive());
  c.settings.refine_normals = s->flag_or("refine_normals", true);
  c.settings.smooth_curvature = s->flag_or("smooth_curvature", true);
  c.settings.rebuild_fraction =
      s->number_or("rebuild_fraction", 0.25, NumberRange::open_closed(0.0, 1.0));
  const std::string order = s->choice("movement", {"second-order", "first-order"}, "second-order");
  c.settings.movement = order == "first-order" ? MovementOrder::first : MovementOrder::second;
  read_velocity(*s, c);
}

template <int D>
void read_pde(TomlParameters& root, SurfaceCase<D>& c) {
  if (!root.has("pde")) return;  // the cloud only moves
  auto p = root.sub_table("pde", true);
  std::vector<std::string> names;
  for (const auto& m : surface_pde_models<D>()) names.push_back(m.name);
  const std::string model = p->choice("model", names);
  for (const auto& m : surface_pde_models<D>())
    if (m.name == model) c.pde = m.make(*p);
  if (!c.pde) p->ignore_rest();
}

template <int D>
void read_solver(TomlParameters& root, SurfaceCase<D>& c) {
  auto s = root.sub_table("solver", true);
  c.settings.end_time = s->number("end_time", NumberRange::positive());
  c.settings.dt = s->number("dt", NumberRange::positive());
  c.settings.solver.tolerance =
      s->number_or("tolerance", 1e-10, NumberRange::open_closed(0.0, 1.0));
  c.settings.solver.max_iterations =
      static_cast<int>(s->integer_or("max_iterations", 500, 1, 1000000));
  c.settings.solver.preconditioner =
      s->choice("preconditioner", {"ilu", "jacobi"}, "ilu") == "jacobi" ? Preconditioner::jacobi
                                                                        : Preconditioner::ilu;
  if (c.settings.dt > c.settings.end_time)
    s->fail("dt", "expected a time step no longer than end_time");
}

template <int D>
void read_output(TomlParameters& root, SurfaceCase<D>& c) {
  auto o = root.sub_table("output", false);
  c.output = read_output_settings(*o, c.name, c.settings.end_time);
  if (!o->has("monitors")) return;
  auto monitors = o->sub_table("monitors", true);
  const toml::node* node = o->take("monitors");
  if (const toml::table* table = node ? node->as_table() : nullptr)
    for (const auto& [key, value] : *table)
      c.monitors.emplace_back(std::string(key.str()), read_formula(*monitors, key.str()));
}

}  // namespace

template <int D>
SurfaceCase<D> read_surface_case(const CaseSource& source) {
  SurfaceCase<D> c;
  c.file = source.file;
  ProblemList problems{source.file, {}};
  std::uint64_t seed = 1;
  {
    TomlParameters root(source.root, "", problems);
    auto meta = root.sub_table("case", false);
    c.name = read_name_or(*meta, "name", std::filesystem::path(source.file).stem().string());
    c.title = meta->text_or("title", c.name);
    c.source = meta->text_or("source", "");
    read_surface(root, c, seed);
    read_solver(root, c);
    read_pde(root, c);
    read_output(root, c);
  }  // unknown keys are reported as the readers go out of scope
  problems.throw_if_any();
  // Before the cloud is sampled: a shape far larger than its spacing would not fit.
  refuse_oversized_surface<D>(c.shapes(), c.spacing, c.spacing_where, "surface.smoothing_length");
  for (std::size_t k = 0; k < c.surfaces.size(); ++k) {
    const PointSample<D> part = c.surfaces[k].shape->sample({c.spacing, seed + k});
    c.sample.points.insert(c.sample.points.end(), part.points.begin(), part.points.end());
    c.sample.normals.insert(c.sample.normals.end(), part.normals.begin(), part.normals.end());
    c.sample.boundary.insert(c.sample.boundary.end(), part.boundary.begin(), part.boundary.end());
    c.sample_surface.insert(c.sample_surface.end(), part.size(), static_cast<int>(k));
  }
  return c;
}

template <int D>
std::unique_ptr<SurfaceSimulation<D>> build_surface_simulation(SurfaceCase<D>& c) {
  return build_surface_simulation<D>(c.sample, c.smoothing_length, c.settings, c.velocity,
                                     std::move(c.pde), &c.sample_surface);
}

template SurfaceCase<2> read_surface_case<2>(const CaseSource&);
template SurfaceCase<3> read_surface_case<3>(const CaseSource&);
template std::unique_ptr<SurfaceSimulation<2>> build_surface_simulation<2>(SurfaceCase<2>&);
template std::unique_ptr<SurfaceSimulation<3>> build_surface_simulation<3>(SurfaceCase<3>&);

}  // namespace pellicle
