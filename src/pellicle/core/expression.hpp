#pragma once
//! Formulas in case files: velocity fields, initial conditions, sources and exact solutions
//! of surface problems, e.g. "exp(-6*t)*x*y". Compiled once into a small stack program over
//! named variables, then evaluated per point.
//!
//! Grammar: + − * / ^ (right-associative), unary minus, comparisons < <= > >= (1 or 0),
//! parentheses, numbers, the constants pi and e, the variables the caller names, and the
//! functions sin cos tan asin acos atan sinh cosh tanh exp log sqrt abs sign floor (one
//! argument), atan2 min max pow (two), if(condition, then, else).

#include <stdexcept>
#include <string>
#include <vector>

namespace pellicle {

//! A formula that does not parse; `column` is 1-based within the formula text.
class ExpressionError : public std::runtime_error {
 public:
  ExpressionError(int column, const std::string& message)
      : std::runtime_error(message), column_(column) {}
  int column() const { return column_; }

 private:
  int column_;
};

class Expression {
 public:
  Expression() = default;
  //! Compile `text` over `variables` (evaluate() takes their values in this order).
  //! Throws ExpressionError.
  Expression(const std::string& text, const std::vector<std::string>& variables);

  double evaluate(const double* values) const;
  double evaluate(const std::vector<double>& values) const { return evaluate(values.data()); }
  //! Whether the formula reads variable k (a velocity that never reads φ needs no φ).
  bool uses(int variable) const;
  const std::string& text() const { return text_; }
  bool empty() const { return code_.empty(); }
  //! Most values a formula may hold pending while it is evaluated.
  static constexpr int kMaxDepth = 64;

 private:
  enum class Op : unsigned char;
  struct Instruction {
    Op op;
    int index;  //!< variable index or function id
    double value;
  };
  std::string text_;
  std::vector<Instruction> code_;
  int max_stack_ = 0;
  friend class ExpressionParser;
};

}  // namespace pellicle
