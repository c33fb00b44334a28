#include "pellicle/core/error.hpp"

#include <sstream>

namespace pellicle {

std::string InputProblem::format() const {
  std::ostringstream out;
  out << (where.file.empty() ? "<input>" : where.file);
  if (where.line > 0) out << ':' << where.line << ':' << where.column;
  out << ": ";
  if (!key.empty()) out << key << ": ";
  out << message;
  return out.str();
}

namespace {
std::string join(const std::vector<InputProblem>& problems) {
  std::string all;
  for (const auto& p : problems) {
    if (!all.empty()) all += '\n';
    all += p.format();
  }
  return all;
}

std::string describe(const NumericalError::Context& c, const std::string& what) {
  std::ostringstream out;
  out << "numerical failure at t=" << c.time << " (step " << c.step << ")";
  if (!c.body.empty()) out << ", body '" << c.body << "'";
  if (c.point >= 0) out << ", point " << c.point;
  out << ": " << what;
  return out.str();
}
}  // namespace

InputError::InputError(std::vector<InputProblem> problems)
    : std::runtime_error(join(problems)), problems_(std::move(problems)) {}

InputError::InputError(SourceLocation where, std::string key, std::string message)
    : InputError(
          std::vector<InputProblem>{{std::move(where), std::move(key), std::move(message)}}) {}

NumericalError::NumericalError(Context context, const std::string& what)
    : std::runtime_error(describe(context, what)), context_(std::move(context)), reason_(what) {}

}  // namespace pellicle
