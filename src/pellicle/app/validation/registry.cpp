//! The validation problems: one file each, one line here.
#include <cstdio>

#include "pellicle/app/validation/problem.hpp"

namespace pellicle::validation {

const std::vector<Problem>& problems() {
  static const std::vector<Problem> list = {
      {"bar-vibration", "Free–free elastic bar, axial period (2D and 3D, every kernel)",
       "thesis ch. 3, ch. 8", &bar_vibration},
      {"cylinder-radial", "Solid cylinder, radial modes (axisymmetric)", "thesis §6.3 formulation",
       &cylinder_radial_vibration},
      {"two-disks", "Two elastic disks collide and rebound", "Sulsky, Chen & Schreyer 1994",
       &two_disks},
      {"two-bars-stick", "Two-bar impact, single velocity field: the bars stick",
       "IJNME 1999 §4.1 Fig. 18; thesis A.1.2", &two_bars_stick},
  };
  return list;
}

const Problem* find_problem(const std::string& name) {
  for (const auto& p : problems())
    if (p.name == name) return &p;
  return nullptr;
}

std::string Check::describe() const {
  char text[512];
  std::snprintf(text, sizeof text, "%s = %.6g%s%s (reference %.6g, accepted [%.6g, %.6g]) %s",
                quantity.c_str(), measured, unit.empty() ? "" : " ", unit.c_str(), reference, lower,
                upper, passed() ? "ok" : "FAILED");
  return text;
}

}  // namespace pellicle::validation
