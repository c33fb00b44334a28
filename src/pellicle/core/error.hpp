#pragma once
//! The two kinds of failure a user can meet, each with its own exit code:
//! bad input (exit 2) and numerical failure during a run (exit 3).

#include <stdexcept>
#include <string>
#include <vector>

namespace pellicle {

//! Process exit codes of the `pellicle` command.
enum ExitCode : int {
  kExitOk = 0,
  kExitCheckFailed = 1,  //!< `pellicle validate`: a measured value outside its accepted range
  kExitBadInput = 2,
  kExitNumericalFailure = 3,
};

//! Where in an input a problem was found. Line and column are 1-based; 0 means unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

//! One problem with the input: `file:line:col: key: message`.
struct InputProblem {
  SourceLocation where;
  std::string key;
  std::string message;  //!< "expected …, found …" or a plain statement
  std::string format() const;
};

//! Input that cannot be run. Holds every problem found, so users fix them all at once.
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<InputProblem> problems);
  InputError(SourceLocation where, std::string key, std::string message);
  const std::vector<InputProblem>& problems() const { return problems_; }

 private:
  std::vector<InputProblem> problems_;
};

//! A simulation assembled from parts that do not work together (USF with a contact model,
//! a body without points, …), found by the engine itself when it is built from C++. The
//! case reader reports the same problems with their file location first. Exit code 2.
class SetupError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

//! The state of a run became unusable (NaN, a point left the grid, CFL above one, …).
class NumericalError : public std::runtime_error {
 public:
  struct Context {
    double time = 0.0;
    long step = 0;
    std::string body;  //!< empty when the failure is not tied to a body
    long point = -1;   //!< index within the body, -1 when not tied to a point
  };
  NumericalError(Context context, const std::string& what);
  const Context& context() const { return context_; }
  //! The failure without its time, step, body and point (to restate it with another context).
  const std::string& reason() const { return reason_; }

 private:
  Context context_;
  std::string reason_;
};

}  // namespace pellicle
