#include "pellicle/core/expression.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>

namespace pellicle {

enum class Expression::Op : unsigned char {
  constant,
  variable,
  add,
  subtract,
  multiply,
  divide,
  power,
  negate,
  less,
  less_equal,
  greater,
  greater_equal,
  function1,
  function2,
  select
};

namespace {

struct Function {
  const char* name;
  int arguments;
};
constexpr Function kFunctions[] = {
    {"sin", 1},   {"cos", 1},   {"tan", 1}, {"asin", 1}, {"acos", 1}, {"atan", 1}, {"sinh", 1},
    {"cosh", 1},  {"tanh", 1},  {"exp", 1}, {"log", 1},  {"sqrt", 1}, {"abs", 1},  {"sign", 1},
    {"floor", 1}, {"atan2", 2}, {"min", 2}, {"max", 2},  {"pow", 2},  {"if", 3}};

double call1(int f, double a) {
  switch (f) {
    case 0:
      return std::sin(a);
    case 1:
      return std::cos(a);
    case 2:
      return std::tan(a);
    case 3:
      return std::asin(a);
    case 4:
      return std::acos(a);
    case 5:
      return std::atan(a);
    case 6:
      return std::sinh(a);
    case 7:
      return std::cosh(a);
    case 8:
      return std::tanh(a);
    case 9:
      return std::exp(a);
    case 10:
      return std::log(a);
    case 11:
      return std::sqrt(a);
    case 12:
      return std::abs(a);
    case 13:
      return (a > 0.0) - (a < 0.0);
    default:
      return std::floor(a);
  }
}

double call2(int f, double a, double b) {
  switch (f) {
    case 15:
      return std::atan2(a, b);
    case 16:
      return std::min(a, b);
    case 17:
      return std::max(a, b);
    default:
      return std::pow(a, b);
  }
}

}  // namespace

//! Recursive descent over the grammar of expression.hpp, emitting postfix code.
class ExpressionParser {
 public:
  ExpressionParser(Expression& out, const std::vector<std::string>& variables)
      : out_(out), text_(out.text_), variables_(variables) {}

  void parse() {
    comparison();
    skip_space();
    if (pos_ < text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "'");
    int depth = 0;
    for (const auto& in : out_.code_) {
      depth += effect(in.op);
      out_.max_stack_ = std::max(out_.max_stack_, depth);
    }
    if (out_.max_stack_ > Expression::kMaxDepth)
      throw ExpressionError(1, "formula nested too deeply (more than " +
                                   std::to_string(Expression::kMaxDepth) + " pending values): \"" +
                                   text_ + "\"");
  }

 private:
  using Op = Expression::Op;
  static int effect(Op op) {
    switch (op) {
      case Op::constant:
      case Op::variable:
        return 1;
      case Op::negate:
      case Op::function1:
        return 0;
      case Op::select:
        return -2;
      default:
        return -1;
    }
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw ExpressionError(static_cast<int>(pos_) + 1, message + " in formula \"" + text_ + "\"");
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool accept(const char* token) {
    skip_space();
    const std::size_t n = std::char_traits<char>::length(token);
    if (text_.compare(pos_, n, token) != 0) return false;
    pos_ += n;
    return true;
  }
  void emit(Op op, int index = 0, double value = 0.0) { out_.code_.push_back({op, index, value}); }

  void comparison() {
    sum();
    for (;;) {
      if (accept("<=")) {
        sum();
        emit(Op::less_equal);
      } else if (accept(">=")) {
        sum();
        emit(Op::greater_equal);
      } else if (accept("<")) {
        sum();
        emit(Op::less);
      } else if (accept(">")) {
        sum();
        emit(Op::greater);
      } else
        return;
    }
  }
  void sum() {
    product();
    for (;;) {
      if (accept("+")) {
        product();
        emit(Op::add);
      } else if (accept("-")) {
        product();
        emit(Op::subtract);
      } else
        return;
    }
  }
  void product() {
    unary();
    for (;;) {
      if (accept("*")) {
        unary();
        emit(Op::multiply);
      } else if (accept("/")) {
        unary();
        emit(Op::divide);
      } else
        return;
    }
  }
  void unary() {
    if (accept("-")) {
      unary();
      emit(Op::negate);
      return;
    }
    if (accept("+")) {
      unary();
      return;
    }
    power();
  }
  void power() {
    primary();
    if (accept("^")) {
      unary();
      emit(Op::power);
    }  // right-associative: 2^3^2 = 2^9
  }
  void primary() {
    skip_space();
    if (pos_ >= text_.size()) fail("expected a number, a name or '('");
    const char c = text_[pos_];
    if (accept("(")) {
      comparison();
      if (!accept(")")) fail("expected ')'");
      return;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const char* start = text_.c_str() + pos_;
      char* end = nullptr;
      const double v = std::strtod(start, &end);
      if (end == start) fail("malformed number");
      pos_ += static_cast<std::size_t>(end - start);
      emit(Op::constant, 0, v);
      return;
    }
    if (!std::isalpha(static_cast<unsigned char>(c)) && c != '_')
      fail("unexpected '" + std::string(1, c) + "'");
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      ++pos_;
    const std::string name = text_.substr(start, pos_ - start);
    if (accept("(")) return call(name, start);
    for (std::size_t k = 0; k < variables_.size(); ++k)
      if (variables_[k] == name) return emit(Op::variable, static_cast<int>(k));
    if (name == "pi") return emit(Op::constant, 0, std::numbers::pi);
    if (name == "e") return emit(Op::constant, 0, std::numbers::e);
    pos_ = start;
    std::string known;
    for (const auto& v : variables_) known += (known.empty() ? "" : ", ") + v;
    fail("unknown name '" + name + "' (variables: " + known + "; constants pi, e)");
  }
  void call(const std::string& name, std::size_t start) {
    int id = -1;
    for (int k = 0; k < static_cast<int>(std::size(kFunctions)); ++k)
      if (name == kFunctions[k].name) id = k;
    if (id < 0) {
      pos_ = start;
      fail("unknown function '" + name + "'");
    }
    int count = 0;
    if (!accept(")")) {
      do {
        comparison();
        ++count;
      } while (accept(","));
      if (!accept(")")) fail("expected ',' or ')'");
    }
    if (count != kFunctions[id].arguments) {
      pos_ = start;
      fail(name + " takes " + std::to_string(kFunctions[id].arguments) + " argument" +
           (kFunctions[id].arguments == 1 ? "" : "s") + ", found " + std::to_string(count));
    }
    emit(count == 1 ? Op::function1 : count == 2 ? Op::function2 : Op::select, id);
  }

  Expression& out_;
  const std::string& text_;
  const std::vector<std::string>& variables_;
  std::size_t pos_ = 0;
};

Expression::Expression(const std::string& text, const std::vector<std::string>& variables)
    : text_(text) {
  ExpressionParser(*this, variables).parse();
  // A formula that reads no variable has one value: "1/0" or "sqrt(-1)" is refused here
  // rather than found at the first step.
  const bool constant = std::none_of(code_.begin(), code_.end(),
                                     [](const Instruction& in) { return in.op == Op::variable; });
  if (constant) {
    const double value = evaluate(nullptr);
    if (!std::isfinite(value))
      throw ExpressionError(1, std::string("the formula's value is ") +
                                   (std::isnan(value) ? "not a number" : "infinite") +
                                   ", for every point and time");
  }
}

bool Expression::uses(int variable) const {
  for (const auto& in : code_)
    if (in.op == Op::variable && in.index == variable) return true;
  return false;
}

double Expression::evaluate(const double* values) const {
  double stack[kMaxDepth];
  double* top = stack;  // one past the last value
  for (const auto& in : code_) {
    switch (in.op) {
      case Op::constant:
        *top++ = in.value;
        break;
      case Op::variable:
        *top++ = values[in.index];
        break;
      case Op::negate:
        top[-1] = -top[-1];
        break;
      case Op::function1:
        top[-1] = call1(in.index, top[-1]);
        break;
      case Op::select:
        top -= 2;
        top[-1] = top[-1] != 0.0 ? top[0] : top[1];
        break;
      default: {
        const double b = *--top;
        double& a = top[-1];
        switch (in.op) {
          case Op::add:
            a += b;
            break;
          case Op::subtract:
            a -= b;
            break;
          case Op::multiply:
            a *= b;
            break;
          case Op::divide:
            a /= b;
            break;
          case Op::power:
            a = std::pow(a, b);
            break;
          case Op::less:
            a = a < b;
            break;
          case Op::less_equal:
            a = a <= b;
            break;
          case Op::greater:
            a = a > b;
            break;
          case Op::greater_equal:
            a = a >= b;
            break;
          default:
            a = call2(in.index, a, b);
            break;
        }
      }
    }
  }
  return top[-1];
}

}  // namespace pellicle
