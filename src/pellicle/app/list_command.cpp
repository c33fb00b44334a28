//! `pellicle list`: the names a case or a command accepts, each with its one-line summary.
#include <cstdio>
#include <string>

#include "pellicle/app/commands.hpp"
#include "pellicle/validation/problem.hpp"
#include "pellicle/core/error.hpp"
#include "pellicle/io/builtin_cases.hpp"
#include "pellicle/mpm/materials/material.hpp"
#include "pellicle/mpm/transfer.hpp"
#include "pellicle/normals/frame_estimator.hpp"

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

}  // namespace

int command_list(const std::string& what) {
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
