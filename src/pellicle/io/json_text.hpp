#pragma once
//! JSON scalars for summary files (io/ only).

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace pellicle {

inline std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream out;
  out << std::setprecision(12) << v;
  return out.str();
}

inline std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}
}  // namespace pellicle
