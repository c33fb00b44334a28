#include "pellicle/io/restart.hpp"

#include <algorithm>
#include <set>
#include <sstream>

#include "pellicle/io/case_source.hpp"
#include "pellicle/io/output.hpp"

namespace pellicle {
namespace {

//! Equal TOML values (tables and arrays compared element by element).
std::string as_text(const toml::node& n) {
  std::ostringstream out;
  n.visit([&](const auto& x) { out << x; });
  return out.str();
}
bool same(const toml::node* a, const toml::node* b) {
  return a && b && a->type() == b->type() && as_text(*a) == as_text(*b);
}

//! Top-level tables and keys a restart may change freely.
bool restart_safe(const std::string& table, const std::string& key) {
  static const std::set<std::string> whole{"output", "case", "probe", "contact", "boundary"};
  if (whole.count(table)) return true;
  // The velocity update only changes how point velocities are formed from now on; one that
  // needs a column the checkpoint lacks (APIC's affine velocity after a FLIP run) is refused
  // when the checkpoint is read.
  if (table == "solver")
    return key == "dt" || key == "cfl" || key == "cfl_limit" || key == "end_time" ||
           key == "velocity_update" || key == "flip_fraction" || key == "rebalance";
  if (table == "grid") return key == "boundary";
  return false;
}

//! Keys of a kept body that a restart may change: what acts on it from now on, not the
//! state it starts from (that comes from the checkpoint).
bool body_key_may_change(const std::string& key) {
  return key == "cut_at" || key == "external_force";
}
bool membrane_key_may_change(const std::string& key) {
  return key == "frames" || key == "orientation";
}

//! Two [[body]] tables alike but for the keys a restart may change.
bool same_body(const toml::table& a, const toml::table& b) {
  std::set<std::string> keys;
  for (const auto& [k, v] : a) keys.insert(std::string(k.str()));
  for (const auto& [k, v] : b) keys.insert(std::string(k.str()));
  for (const auto& key : keys) {
    if (body_key_may_change(key)) continue;
    const auto *x = a.get(key), *y = b.get(key);
    if (key == "membrane" && x && y && x->is_table() && y->is_table()) {
      toml::table u = *x->as_table(), v = *y->as_table();
      for (toml::table* t : {&u, &v})
        for (auto it = t->begin(); it != t->end();)
          it = membrane_key_may_change(std::string(it->first.str())) ? t->erase(it) : ++it;
      if (!same(&u, &v)) return false;
      continue;
    }
    if (!same(x, y)) return false;
  }
  return true;
}

//! A kept [[material]] may take new parameters of the same model.
bool same_model(const toml::table& a, const toml::table& b) {
  return same(a.get("model"), b.get("model"));
}

class Comparison {
 public:
  Comparison(const CaseSource& now, std::string checkpoint)
      : now_(now), checkpoint_(std::move(checkpoint)) {}

  void refuse(const toml::node* at, const toml::node* parent, const std::string& key,
              const std::string& what) {
    SourceLocation where{now_.file, 0, 0};
    if (at)
      where = location_of(at->source(), now_.file);
    else if (parent)
      where = location_of(parent->source(), now_.file);
    problems_.push_back({where, key, what + " (restart from " + checkpoint_ + ")"});
  }

  //! Tables other than the named arrays: each key equal, or restart-safe.
  void compare_table(const std::string& name, const toml::table* saved, const toml::table* now) {
    std::set<std::string> keys;
    if (saved)
      for (const auto& [k, v] : *saved) keys.insert(std::string(k.str()));
    if (now)
      for (const auto& [k, v] : *now) keys.insert(std::string(k.str()));
    for (const auto& key : keys) {
      if (restart_safe(name, key)) continue;
      const toml::node* a = saved ? saved->get(key) : nullptr;
      const toml::node* b = now ? now->get(key) : nullptr;
      if (same(a, b)) continue;
      refuse(b, now, name + "." + key,
             "a restart cannot change this key (only solver.dt, cfl, cfl_limit, end_time, "
             "velocity_update, flip_fraction, [output], [contact], [[boundary]], grid.boundary "
             "and added or removed bodies)");
    }
  }

  //! [[body]] / [[material]]: by name; kept entries unchanged; returns the kept names.
  std::set<std::string> compare_named(const std::string& name, const toml::array* saved,
                                      const toml::array* now, const std::set<std::string>& used) {
    std::set<std::string> kept;
    if (!saved || !now) return kept;
    for (const auto& entry : *now) {
      const toml::table* t = entry.as_table();
      const std::string id = t ? t->get("name") ? t->get("name")->value_or(std::string()) : "" : "";
      for (const auto& old : *saved) {
        const toml::table* o = old.as_table();
        if (!o || !o->get("name") || o->get("name")->value_or(std::string()) != id) continue;
        kept.insert(id);
        if (same(o, t)) break;
        if (name == "material" && (!used.count(id) || same_model(*o, *t))) break;
        if (name == "body" && same_body(*o, *t)) break;
        refuse(t, now, name + " '" + id + "'",
               name == "material"
                   ? "a material carried over from the checkpoint may change its parameters "
                     "but not its model; give the changed one a new name to start it afresh"
                   : "a body carried over from the checkpoint may change only cut_at, "
                     "external_force and its membrane's frames and orientation; give the "
                     "changed one a new name to start it afresh");
        break;
      }
    }
    return kept;
  }

  void throw_if_any() const {
    if (!problems_.empty()) throw InputError(problems_);
  }

 private:
  const CaseSource& now_;
  std::string checkpoint_;
  std::vector<InputProblem> problems_;
};

}  // namespace

CheckpointHeader checkpoint_header_for(const CaseSource& source) {
  CheckpointHeader h;
  h.version = PELLICLE_VERSION;
  h.case_file = source.file;
  h.case_text = source.text;
  h.case_hash = hash_text(source.text);
  std::ostringstream toml_text;
  toml_text << source.root;
  h.case_toml = toml_text.str();
  return h;
}

void check_restart(const CheckpointHeader& saved, const std::string& path, const CaseSource& now) {
  const SourceLocation where{path, 0, 0};
  if (saved.version != PELLICLE_VERSION)
    throw InputError(where, "--restart",
                     "written by Pellicle " + saved.version + ", this is " + PELLICLE_VERSION +
                         ": a checkpoint continues only with the version that wrote it");
  if (saved.dimension != case_dimension(now))
    throw InputError(where, "--restart",
                     "a " + std::to_string(saved.dimension) + "D run cannot continue as a " +
                         std::to_string(case_dimension(now)) + "D case");
  const auto old = case_source_from_text(saved.case_toml, path + " (saved case)");
  Comparison compare(now, path);
  std::set<std::string> tables;
  for (const auto& [k, v] : old->root) tables.insert(std::string(k.str()));
  for (const auto& [k, v] : now.root) tables.insert(std::string(k.str()));
  // Bodies first: the materials they keep using must not change.
  std::set<std::string> used;
  const auto* saved_bodies = old->root.get_as<toml::array>("body");
  const auto* new_bodies = now.root.get_as<toml::array>("body");
  const auto kept = compare.compare_named("body", saved_bodies, new_bodies, {});
  if (new_bodies)
    for (const auto& b : *new_bodies)
      if (const auto* t = b.as_table(); t && t->get("name") && t->get("material") &&
                                        kept.count(t->get("name")->value_or(std::string())))
        used.insert(t->get("material")->value_or(std::string()));
  compare.compare_named("material", old->root.get_as<toml::array>("material"),
                        now.root.get_as<toml::array>("material"), used);
  for (const auto& table : tables) {
    if (table == "body" || table == "material" || restart_safe(table, "")) continue;
    const toml::table* a = old->root.get_as<toml::table>(table);
    const toml::table* b = now.root.get_as<toml::table>(table);
    if (a || b) {
      compare.compare_table(table, a, b);
    } else if (!same(old->root.get(table), now.root.get(table))) {
      compare.refuse(now.root.get(table), nullptr, table, "a restart cannot change this key");
    }
  }
  compare.throw_if_any();
}

}  // namespace pellicle
