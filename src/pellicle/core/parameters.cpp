#include "pellicle/core/parameters.hpp"

#include <sstream>

namespace pellicle {

std::string NumberRange::describe() const {
  std::ostringstream out;
  out << "a number";
  const bool has_min = min > -1e308, has_max = max < 1e308;
  if (has_min && has_max) {
    out << " in " << (min_open ? '(' : '[') << min << ", " << max << (max_open ? ')' : ']');
  } else if (has_min) {
    out << (min_open ? " > " : " >= ") << min;
  } else if (has_max) {
    out << (max_open ? " < " : " <= ") << max;
  }
  return out.str();
}

namespace {

//! Why `name` cannot name an output file or a CSV column, or "" if it can.
std::string name_problem(const std::string& name) {
  if (name.empty()) return "expected a name, found an empty string";
  if (name == "." || name == "..") return "expected a name, found \"" + name + "\"";
  for (const char c : name) {
    if (c == ',' || c == '"' || c == '\'' || c == '/' || c == '\\')
      return std::string(
                 "expected a name without commas, quotes or path separators (it names "
                 "files and CSV columns), found '") +
             c + "' in \"" + name + "\"";
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      return "expected a name without line breaks, tabs or other control characters";
  }
  return "";
}

std::string checked(ParameterReader& in, std::string_view key, std::string name) {
  const std::string problem = name_problem(name);
  if (problem.empty()) return name;
  in.fail(key, problem);
  return "unnamed";
}

}  // namespace

std::string read_name(ParameterReader& in, std::string_view key) {
  if (!in.has(key)) return in.text(key);  // records the missing key
  return checked(in, key, in.text(key));
}

std::string read_name_or(ParameterReader& in, std::string_view key, std::string_view fallback) {
  return in.has(key) ? checked(in, key, in.text(key)) : std::string(fallback);
}

}  // namespace pellicle
