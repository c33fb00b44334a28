// Formulas of case files: precedence, functions, variables, and every rejected formula with
// the column and reason it names.
#include <gtest/gtest.h>

#include <cmath>

#include "pellicle/core/expression.hpp"

namespace pellicle {
namespace {

double eval(const std::string& text, std::vector<double> values = {0.5, -2.0, 3.0}) {
  return Expression(text, {"x", "y", "t"}).evaluate(values);
}

TEST(Expression, PrecedenceAndAssociativity) {
  EXPECT_DOUBLE_EQ(eval("1 + 2*3 - 4/8"), 6.5);
  EXPECT_DOUBLE_EQ(eval("2^3^2"), 512.0);  // right-associative
  EXPECT_DOUBLE_EQ(eval("-2^2"), -4.0);    // unary minus binds looser than ^
  EXPECT_DOUBLE_EQ(eval("(1 + 2) * 3"), 9.0);
  EXPECT_DOUBLE_EQ(eval("2 * -3"), -6.0);
  EXPECT_DOUBLE_EQ(eval("1.5e-3 * 2e3"), 3.0);
  EXPECT_DOUBLE_EQ(eval("1 < 2") + eval("2 <= 2") + eval("3 > 4") + eval("4 >= 5"), 2.0);
  EXPECT_DOUBLE_EQ(eval("1 + 1 < 3"), 1.0);  // comparisons bind loosest
}

TEST(Expression, VariablesFunctionsAndConstants) {
  EXPECT_DOUBLE_EQ(eval("exp(-6*t)*x*y"), std::exp(-18.0) * -1.0);
  EXPECT_DOUBLE_EQ(eval("sqrt(x^2 + y^2)"), std::sqrt(4.25));
  EXPECT_DOUBLE_EQ(eval("atan2(y, x)"), std::atan2(-2.0, 0.5));
  EXPECT_DOUBLE_EQ(eval("min(x, y) + max(x, y) + pow(t, 2)"), -1.5 + 9.0);
  EXPECT_DOUBLE_EQ(eval("sign(y) + abs(y) + floor(x)"), -1.0 + 2.0 + 0.0);
  EXPECT_DOUBLE_EQ(eval("if(x > 0, 10, 20) + if(y > 0, 1, 2)"), 12.0);
  EXPECT_DOUBLE_EQ(eval("2*pi*cos(2*pi*t)*sin(pi/2*x)"),
                   2 * M_PI * std::cos(6 * M_PI) * std::sin(M_PI / 4));
  EXPECT_DOUBLE_EQ(eval("e"), std::exp(1.0));
  const Expression f("0.5*phi*nx - y*z", {"x", "y", "z", "phi", "nx"});
  EXPECT_TRUE(f.uses(3));
  EXPECT_FALSE(f.uses(0));
}

void expect_rejected(const std::string& text, int column, const std::string& words) {
  try {
    Expression(text, {"x", "y", "t"});
    FAIL() << "accepted " << text;
  } catch (const ExpressionError& e) {
    EXPECT_EQ(e.column(), column) << text << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(Expression, RejectedFormulasNameColumnAndReason) {
  expect_rejected("x + q", 5, "unknown name 'q' (variables: x, y, t");
  expect_rejected("foo(x)", 1, "unknown function 'foo'");
  expect_rejected("sin(x, y)", 1, "sin takes 1 argument, found 2");
  expect_rejected("(x + 1", 7, "expected ')'");
  expect_rejected("x + ", 5, "expected a number, a name or '('");
  expect_rejected("x y", 3, "unexpected 'y'");
  expect_rejected("x $ 2", 3, "unexpected '$'");
  expect_rejected("", 1, "expected a number");
  // A formula without variables has one value, known when it is read.
  expect_rejected("1/0", 1, "the formula's value is infinite");
  expect_rejected("sqrt(-1)", 1, "the formula's value is not a number");
  EXPECT_TRUE(std::isinf(eval("1/x", {0.0, 0.0, 0.0})));  // a value at some points only: allowed
}

}  // namespace
}  // namespace pellicle
