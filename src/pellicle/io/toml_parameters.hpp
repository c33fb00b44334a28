#pragma once
//! ParameterReader over a toml++ table: typed getters that record every problem with
//! `file:line:col: key: expected …, found …`, and report keys nobody asked for.
//! toml++ stays inside io/: only this header and case files include it.

#include <memory>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "pellicle/core/error.hpp"
#include "pellicle/core/parameters.hpp"

namespace pellicle {

//! Where problems found while reading one input accumulate.
struct ProblemList {
  std::string file;
  std::vector<InputProblem> problems;
  void add(const toml::node* where, std::string key, std::string message);
  //! Throw InputError when anything was recorded.
  void throw_if_any() const;
};

class TomlParameters final : public ParameterReader {
 public:
  //! `path` is the table's name for messages ("" for the root, "grid", "body[1]").
  TomlParameters(const toml::table& table, std::string path, ProblemList& problems);
  //! Records every key of the table that was never read as unknown.
  ~TomlParameters() override;
  TomlParameters(const TomlParameters&) = delete;
  TomlParameters& operator=(const TomlParameters&) = delete;

  std::string path() const override { return path_; }
  bool has(std::string_view key) const override;
  double number(std::string_view key, NumberRange range) override;
  double number_or(std::string_view key, double fallback, NumberRange range) override;
  long integer_or(std::string_view key, long fallback, long min, long max) override;
  bool flag_or(std::string_view key, bool fallback) override;
  std::string choice(std::string_view key, const std::vector<std::string>& options,
                     std::string_view fallback = {}) override;
  std::string text(std::string_view key) override;
  std::string text_or(std::string_view key, std::string_view fallback) override;
  std::vector<double> numbers(std::string_view key, int count, NumberRange range) override;
  std::vector<std::vector<double>> number_lists(std::string_view key, int inner) override;
  std::unique_ptr<ParameterReader> table(std::string_view key) override;
  std::vector<std::unique_ptr<ParameterReader>> tables(std::string_view key) override;
  void fail(std::string_view key, std::string message) override;
  void ignore_rest() override;

  //! Typed access for io/ itself (sub-table as TomlParameters).
  std::unique_ptr<TomlParameters> sub_table(std::string_view key, bool required);
  std::vector<std::unique_ptr<TomlParameters>> sub_tables(std::string_view key);
  //! Where this table starts in the input.
  SourceLocation location() const;
  //! Where `key` is given, or the table when it is not.
  SourceLocation location(std::string_view key) const;
  //! Mark a key as understood without reading it through a getter.
  const toml::node* take(std::string_view key);

 private:
  std::string qualified(std::string_view key) const;
  void asked(std::string_view key) const;
  void missing(std::string_view key, const std::string& expected);
  void wrong(const toml::node* node, std::string_view key, const std::string& expected);
  bool read_number(const toml::node& node, std::string_view key, NumberRange range, double& out);

  const toml::table& table_;
  std::string path_;
  ProblemList& problems_;
  std::set<std::string, std::less<>> used_;
};

//! Records, while it lives, every key a TomlParameters on this thread is asked for (read,
//! taken or tested with has()), qualified by its table's path: "body[1].region.radius".
//! The unit tests read every built-in case under one to check that docs/user-guide.md
//! documents each key the readers know. Without one, asking costs a thread-local test.
class AskedKeys {
 public:
  AskedKeys();
  ~AskedKeys();
  AskedKeys(const AskedKeys&) = delete;
  AskedKeys& operator=(const AskedKeys&) = delete;
  const std::set<std::string>& keys() const { return keys_; }

 private:
  friend class TomlParameters;
  std::set<std::string> keys_;
  AskedKeys* outer_;  //!< the recorder this one replaced, restored when it ends
};

//! "a string \"usl\"", "an integer 3", "an array of 2 elements": what a node holds.
std::string describe_node(const toml::node& node);

}  // namespace pellicle
