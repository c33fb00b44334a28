//! `pellicle list`: the names a case or a command accepts, each with its one-line summary,
//! and the keys a case file can hold.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "pellicle/app/commands.hpp"
#include "pellicle/core/error.hpp"
#include "pellicle/io/builtin_cases.hpp"
#include "pellicle/io/case_keys.hpp"
#include "pellicle/mpm/materials/material.hpp"
#include "pellicle/mpm/transfer.hpp"
#include "pellicle/normals/frame_estimator.hpp"
#include "pellicle/validation/problem.hpp"

namespace pellicle {

namespace {

//! The value of `key = "…"` in a case's [case] table, or "".
std::string case_value(const std::string& text, const std::string& key) {
  const std::string prefix = "\n" + key + " = \"";
  const auto at = text.find(prefix);
  if (at == std::string::npos) return "";
  const auto begin = at + prefix.size();
  return text.substr(begin, text.find('"', begin) - begin);
}

void row(const std::string& name, const std::string& summary) {
  std::printf("%-28s %s\n", name.c_str(), summary.c_str());
}

//! Every documented key under `section` (all keys when empty), one a line:
//! `section.key (where)  type | unit | default | meaning`, each section's keys together (the
//! guide documents surface cases' [solver] apart from MPM cases', regions after bodies).
int list_keys(const std::string& section) {
  std::vector<const DocumentedKey*> chosen;
  std::vector<std::string> sections;  // in the order the guide first names them
  const auto section_of = [](const DocumentedKey& k) { return k.key.substr(0, k.key.find('.')); };
  for (const DocumentedKey& k : documented_keys()) {
    if (std::find(sections.begin(), sections.end(), section_of(k)) == sections.end())
      sections.push_back(section_of(k));
    if (section.empty() || k.key == section || k.key.rfind(section + ".", 0) == 0)
      chosen.push_back(&k);
  }
  std::stable_sort(chosen.begin(), chosen.end(), [&](const auto* a, const auto* b) {
    return std::find(sections.begin(), sections.end(), section_of(*a)) <
           std::find(sections.begin(), sections.end(), section_of(*b));
  });
  if (chosen.empty()) {
    std::string known;
    for (const auto& s : sections) known += (known.empty() ? "" : ", ") + s;
    std::fprintf(
        stderr, "pellicle: error: list keys: no key under \"%s\" in the user guide; sections: %s\n",
        section.c_str(), known.c_str());
    return kExitBadInput;
  }
  const auto name_of = [](const DocumentedKey* k) {
    return k->where.empty() ? k->key : k->key + " (" + k->where + ")";
  };
  int width = 24;  // the names' column, as wide as the longest name up to 48 characters
  for (const DocumentedKey* k : chosen)
    width = std::max(width, std::min(48, static_cast<int>(name_of(k).size())));
  const auto or_dash = [](const std::string& s) { return s.empty() ? std::string("-") : s; };
  std::printf("%-*s %s\n", width, "key (where it applies)", "type | unit | default | meaning");
  for (const DocumentedKey* k : chosen)
    std::printf("%-*s %s | %s | %s | %s\n", width, name_of(k).c_str(), or_dash(k->type).c_str(),
                or_dash(k->unit).c_str(), or_dash(k->default_value).c_str(),
                or_dash(k->meaning).c_str());
  return kExitOk;
}

}  // namespace

int command_list(const std::string& what, const std::string& section) {
  if (what == "keys") return list_keys(section);
  if (!section.empty()) {
    std::fprintf(stderr, "pellicle: error: list %s: takes no further word, found \"%s\"\n",
                 what.c_str(), section.c_str());
    return kExitBadInput;
  }
  if (what == "cases") {
    for (const auto& [file, text] : builtin_cases())
      row("cases/" + file, case_value(text, "title"));
  } else if (what == "problems") {
    for (const auto& p : validation::problems()) row(p.name, p.title + " (" + p.source + ")");
  } else if (what == "estimators") {
    for (const auto& e : frame_estimators<3>()) row(e.name, e.summary);
  } else if (what == "kernels") {
    for (const auto& k : kernel_choices<3>()) row(k.name, k.summary);
  } else if (what == "materials") {
    for (const auto& m : material_models<3>()) row(m.name, m.summary);
  }
  return kExitOk;
}

}  // namespace pellicle
