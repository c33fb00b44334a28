#include "pellicle/io/toml_parameters.hpp"

#include <cmath>
#include <sstream>

namespace pellicle {

namespace {
SourceLocation location_of(const toml::node* node, const std::string& file) {
  SourceLocation where{file, 0, 0};
  if (node) {
    const auto& src = node->source();
    if (src.path && !src.path->empty()) where.file = *src.path;
    // Values from `--set` are named by the setting itself; their line and column say nothing.
    if (where.file.rfind("--set ", 0) != 0) {
      where.line = static_cast<int>(src.begin.line);
      where.column = static_cast<int>(src.begin.column);
    }
  }
  return where;
}

thread_local AskedKeys* recorder = nullptr;

std::string list_options(const std::vector<std::string>& options) {
  std::string s;
  for (std::size_t i = 0; i < options.size(); ++i) {
    if (i) s += i + 1 == options.size() ? " or " : ", ";
    s += '"' + options[i] + '"';
  }
  return s;
}
}  // namespace

void ProblemList::add(const toml::node* where, std::string key, std::string message) {
  problems.push_back({location_of(where, file), std::move(key), std::move(message)});
}

void ProblemList::throw_if_any() const {
  if (!problems.empty()) throw InputError(problems);
}

std::string describe_node(const toml::node& node) {
  std::ostringstream out;
  switch (node.type()) {
    case toml::node_type::string:
      out << "the string \"" << *node.value<std::string>() << '"';
      break;
    case toml::node_type::integer:
      out << "the integer " << *node.value<int64_t>();
      break;
    case toml::node_type::floating_point:
      out << "the number " << *node.value<double>();
      break;
    case toml::node_type::boolean:
      out << (*node.value<bool>() ? "true" : "false");
      break;
    case toml::node_type::array:
      out << "an array of " << node.as_array()->size() << " elements";
      break;
    case toml::node_type::table:
      out << "a table";
      break;
    default:
      out << "a date or time";
      break;
  }
  return out.str();
}

AskedKeys::AskedKeys() : outer_(recorder) {
  recorder = this;
}

AskedKeys::~AskedKeys() {
  recorder = outer_;
}

void TomlParameters::asked(std::string_view key) const {
  if (recorder) recorder->keys_.insert(qualified(key));
}

TomlParameters::TomlParameters(const toml::table& table, std::string path, ProblemList& problems)
    : table_(table), path_(std::move(path)), problems_(problems) {}

TomlParameters::~TomlParameters() {
  for (const auto& [key, node] : table_) {
    if (used_.count(key.str())) continue;
    SourceLocation where = location_of(&node, problems_.file);
    if (key.source().begin.line > 0) {  // point at the key itself, not its value
      where.line = static_cast<int>(key.source().begin.line);
      where.column = static_cast<int>(key.source().begin.column);
    }
    problems_.problems.push_back(
        {where, qualified(key.str()), "unknown key (misspelt, or not used by this model)"});
  }
}

std::string TomlParameters::qualified(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void TomlParameters::missing(std::string_view key, const std::string& expected) {
  problems_.add(&table_, qualified(key), "expected " + expected + ", found nothing (required)");
}

void TomlParameters::wrong(const toml::node* node, std::string_view key,
                           const std::string& expected) {
  problems_.add(node, qualified(key), "expected " + expected + ", found " + describe_node(*node));
}

const toml::node* TomlParameters::take(std::string_view key) {
  asked(key);
  used_.emplace(key);
  return table_.get(key);
}

SourceLocation TomlParameters::location() const {
  return location_of(&table_, problems_.file);
}

SourceLocation TomlParameters::location(std::string_view key) const {
  const toml::node* node = table_.get(key);
  return location_of(node ? node : &table_, problems_.file);
}

bool TomlParameters::has(std::string_view key) const {
  asked(key);
  return table_.contains(key);
}

bool TomlParameters::read_number(const toml::node& node, std::string_view key, NumberRange range,
                                 double& out) {
  std::optional<double> v;
  if (node.is_floating_point()) v = node.value<double>();
  if (node.is_integer()) v = static_cast<double>(*node.value<int64_t>());
  // Infinity only where the range reaches it (a friction coefficient of inf: no slip).
  const bool infinite_allowed = v && *v > 0.0 && std::isinf(range.max);
  if (!v || std::isnan(*v) || (std::isinf(*v) && !infinite_allowed) || !range.admits(*v)) {
    wrong(&node, key, range.describe());
    return false;
  }
  // Below 2.2e-308 a double loses its precision and its reciprocal overflows: no physical
  // input is that small in SI units.
  if (std::fpclassify(*v) == FP_SUBNORMAL) {
    wrong(&node, key, range.describe() + " of normal size (0 or at least 2.2e-308 in magnitude)");
    return false;
  }
  out = *v;
  return true;
}

double TomlParameters::number(std::string_view key, NumberRange range) {
  const toml::node* node = take(key);
  if (!node) {
    missing(key, range.describe());
    return range.admits(1.0) ? 1.0 : range.min;
  }
  double v = range.admits(1.0) ? 1.0 : range.min;
  read_number(*node, key, range, v);
  return v;
}

double TomlParameters::number_or(std::string_view key, double fallback, NumberRange range) {
  const toml::node* node = take(key);
  if (!node) return fallback;
  double v = fallback;
  read_number(*node, key, range, v);
  return v;
}

long TomlParameters::integer_or(std::string_view key, long fallback, long min, long max) {
  const toml::node* node = take(key);
  if (!node) return fallback;
  const auto v = node->value_exact<int64_t>();
  if (!v || *v < min || *v > max) {
    wrong(node, key, "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
    return fallback;
  }
  return static_cast<long>(*v);
}

bool TomlParameters::flag_or(std::string_view key, bool fallback) {
  const toml::node* node = take(key);
  if (!node) return fallback;
  const auto v = node->value_exact<bool>();
  if (!v) {
    wrong(node, key, "true or false");
    return fallback;
  }
  return *v;
}

std::string TomlParameters::choice(std::string_view key, const std::vector<std::string>& options,
                                   std::string_view fallback) {
  const std::string expected = "one of " + list_options(options);
  const toml::node* node = take(key);
  if (!node) {
    if (fallback.empty()) missing(key, expected);
    return std::string(fallback);
  }
  const auto v = node->value_exact<std::string>();
  if (v)
    for (const auto& o : options)
      if (*v == o) return o;
  wrong(node, key, expected);
  return std::string(fallback);
}

std::string TomlParameters::text(std::string_view key) {
  const toml::node* node = take(key);
  if (!node) {
    missing(key, "a string");
    return {};
  }
  const auto v = node->value_exact<std::string>();
  if (!v) wrong(node, key, "a string");
  return v.value_or("");
}

std::string TomlParameters::text_or(std::string_view key, std::string_view fallback) {
  if (!has(key)) {
    used_.emplace(key);  // has() recorded it as asked
    return std::string(fallback);
  }
  return text(key);
}

std::vector<double> TomlParameters::numbers(std::string_view key, int count, NumberRange range) {
  const std::string expected =
      (count > 0 ? "an array of " + std::to_string(count) : std::string("an array of")) +
      " numbers, each " + range.describe();
  std::vector<double> out(count > 0 ? count : 0, range.admits(0.0) ? 0.0 : range.min);
  const toml::node* node = take(key);
  if (!node) {
    missing(key, expected);
    return out;
  }
  const toml::array* array = node->as_array();
  if (!array || (count > 0 && static_cast<int>(array->size()) != count) || array->empty()) {
    wrong(node, key, expected);
    return out;
  }
  out.assign(array->size(), out.empty() ? 0.0 : out[0]);
  for (std::size_t i = 0; i < array->size(); ++i) {
    const std::string element = std::string(key) + "[" + std::to_string(i) + "]";
    read_number(*array->get(i), element, range, out[i]);
  }
  return out;
}

std::vector<std::vector<double>> TomlParameters::number_lists(std::string_view key, int inner) {
  const std::string expected =
      "an array of points, each an array of " + std::to_string(inner) + " numbers";
  const toml::node* node = take(key);
  std::vector<std::vector<double>> out;
  if (!node) {
    missing(key, expected);
    return out;
  }
  const toml::array* array = node->as_array();
  if (!array || array->empty()) {
    wrong(node, key, expected);
    return out;
  }
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& item = *array->get(i);
    const toml::array* point = item.as_array();
    const std::string element = std::string(key) + "[" + std::to_string(i) + "]";
    std::vector<double> values(inner, 0.0);
    if (!point || static_cast<int>(point->size()) != inner) {
      wrong(&item, element, "an array of " + std::to_string(inner) + " numbers");
    } else {
      for (int d = 0; d < inner; ++d)
        read_number(*point->get(d), element + "[" + std::to_string(d) + "]", NumberRange::any(),
                    values[d]);
    }
    out.push_back(std::move(values));
  }
  return out;
}

std::unique_ptr<TomlParameters> TomlParameters::sub_table(std::string_view key, bool required) {
  static const toml::table empty;
  const toml::node* node = take(key);
  if (!node) {
    if (required) missing(key, "a table");
    return std::make_unique<TomlParameters>(empty, qualified(key), problems_);
  }
  if (!node->is_table()) {
    wrong(node, key, "a table");
    return std::make_unique<TomlParameters>(empty, qualified(key), problems_);
  }
  return std::make_unique<TomlParameters>(*node->as_table(), qualified(key), problems_);
}

std::vector<std::unique_ptr<TomlParameters>> TomlParameters::sub_tables(std::string_view key) {
  std::vector<std::unique_ptr<TomlParameters>> out;
  const toml::node* node = take(key);
  const std::string expected = "an array of tables ([[" + std::string(key) + "]])";
  if (!node) {
    missing(key, expected);
    return out;
  }
  const toml::array* array = node->as_array();
  if (!array || array->empty()) {
    wrong(node, key, expected);
    return out;
  }
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& item = *array->get(i);
    const std::string name = qualified(key) + "[" + std::to_string(i) + "]";
    if (!item.is_table()) {
      problems_.add(&item, name, "expected a table, found " + describe_node(item));
      continue;
    }
    out.push_back(std::make_unique<TomlParameters>(*item.as_table(), name, problems_));
  }
  return out;
}

std::unique_ptr<ParameterReader> TomlParameters::table(std::string_view key) {
  return sub_table(key, true);
}

std::vector<std::unique_ptr<ParameterReader>> TomlParameters::tables(std::string_view key) {
  std::vector<std::unique_ptr<ParameterReader>> out;
  for (auto& t : sub_tables(key)) out.push_back(std::move(t));
  return out;
}

void TomlParameters::ignore_rest() {
  for (const auto& [key, node] : table_) used_.emplace(key.str());
}

void TomlParameters::fail(std::string_view key, std::string message) {
  const toml::node* node = table_.get(key);
  problems_.add(node ? node : &table_, qualified(key), std::move(message));
}

}  // namespace pellicle
