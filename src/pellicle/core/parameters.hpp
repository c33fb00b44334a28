#pragma once
//! A typed, validating view of one table of user input. Models (materials, regions, …) read
//! their parameters through it, so each model declares its own keys next to its physics and
//! the input layer (io/) reports every problem with file, line, column and key.
//!
//! Getters never throw: on a problem they record it and return a harmless fallback, so one
//! pass over the input collects every problem. The input layer raises InputError afterwards.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "pellicle/core/types.hpp"

namespace pellicle {

//! Admissible range of a number; bounds are inclusive unless marked open.
struct NumberRange {
  double min = -1e308, max = 1e308;
  bool min_open = false, max_open = false;
  static NumberRange positive() { return {0.0, 1e308, true, false}; }
  static NumberRange non_negative() { return {0.0, 1e308, false, false}; }
  static NumberRange closed(double a, double b) { return {a, b, false, false}; }
  static NumberRange open_closed(double a, double b) { return {a, b, true, false}; }
  static NumberRange any() { return {}; }
  bool admits(double x) const {
    return (min_open ? x > min : x >= min) && (max_open ? x < max : x <= max);
  }
  std::string describe() const;  //!< e.g. "a number > 0"
};

class ParameterReader {
 public:
  virtual ~ParameterReader() = default;

  //! Path of this table in the input, e.g. "material[0]".
  virtual std::string path() const = 0;
  virtual bool has(std::string_view key) const = 0;

  virtual double number(std::string_view key, NumberRange range) = 0;
  virtual double number_or(std::string_view key, double fallback, NumberRange range) = 0;
  virtual long integer_or(std::string_view key, long fallback, long min, long max) = 0;
  virtual bool flag_or(std::string_view key, bool fallback) = 0;
  //! A string out of a fixed set; `fallback` empty means the key is required. On a problem
  //! returns `fallback` (empty for a required key).
  virtual std::string choice(std::string_view key, const std::vector<std::string>& options,
                             std::string_view fallback = {}) = 0;
  virtual std::string text(std::string_view key) = 0;
  virtual std::string text_or(std::string_view key, std::string_view fallback) = 0;
  //! A list of `count` numbers (count < 0: any length ≥ 1), each in `range`.
  virtual std::vector<double> numbers(std::string_view key, int count,
                                      NumberRange range = NumberRange::any()) = 0;
  //! A list of lists, each of `inner` numbers (polygon vertices, control points).
  virtual std::vector<std::vector<double>> number_lists(std::string_view key, int inner) = 0;
  //! A sub-table (required).
  virtual std::unique_ptr<ParameterReader> table(std::string_view key) = 0;
  //! A list of sub-tables (required, at least one).
  virtual std::vector<std::unique_ptr<ParameterReader>> tables(std::string_view key) = 0;

  //! Stop checking this table for unknown keys (after a problem that makes them moot).
  virtual void ignore_rest() = 0;
  //! Record a problem about `key` that the getters cannot express (a cross-key rule).
  virtual void fail(std::string_view key, std::string message) = 0;
};

//! A name that goes into file names and CSV column headers (case, body, material, probe):
//! refuses the empty name, ".", "..", and names with a comma, a quote, a path separator or a
//! control character (records the problem and returns the fallback "unnamed").
std::string read_name(ParameterReader& in, std::string_view key);
//! The same for an optional name.
std::string read_name_or(ParameterReader& in, std::string_view key, std::string_view fallback);

//! A required vector of D numbers.
template <int D>
Vec<D> read_vector(ParameterReader& in, std::string_view key,
                   NumberRange range = NumberRange::any()) {
  const std::vector<double> v = in.numbers(key, D, range);
  Vec<D> x;
  for (int d = 0; d < D; ++d) x[d] = v[d];
  return x;
}

//! An optional vector of D numbers.
template <int D>
Vec<D> read_vector_or(ParameterReader& in, std::string_view key, const Vec<D>& fallback) {
  return in.has(key) ? read_vector<D>(in, key) : fallback;
}

}  // namespace pellicle
