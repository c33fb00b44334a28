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

}  // namespace pellicle
