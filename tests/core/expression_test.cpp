// Verifies that formulas in x and y take the values muParser's syntax gives them (the dam break's
// ternary, the bowl's paraboloid), that copies share one formula, and that a syntax error, an
// unknown variable and a value that is not finite are InputErrors naming the origin and where.
#include "core/expression.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "core/error.hpp"

namespace flotsam {
namespace {

const std::string origin = "case.yaml:12: flow.initial.eta";

// The message of the InputError `f` throws, or "no error".
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Expression, EmptyByDefault) {
  const Expression e;
  EXPECT_TRUE(e.empty());
  EXPECT_EQ(e.text(), "");
  EXPECT_EQ(e.origin(), "");
}

TEST(Expression, ArithmeticAndFunctionsInXAndY) {
  const Expression e("2*x + y^2 - sqrt(4) + sin(0) + max(x, y)", origin);
  EXPECT_FALSE(e.empty());
  EXPECT_EQ(e.text(), "2*x + y^2 - sqrt(4) + sin(0) + max(x, y)");
  EXPECT_EQ(e.origin(), origin);
  EXPECT_DOUBLE_EQ(e(1.5, 3.0), 3.0 + 9.0 - 2.0 + 3.0);
  EXPECT_DOUBLE_EQ(e(-1.0, 0.0), -2.0 - 2.0 + 0.0);
  EXPECT_DOUBLE_EQ(Expression("exp(x) * _pi", origin)(0.0, 0.0), std::numbers::pi);
  EXPECT_EQ(Expression("0.25", origin)(7.0, -3.0), 0.25);
}

TEST(Expression, DamBreakTernary) {
  const Expression eta("x < 5 ? 0.005 : 0", origin);
  EXPECT_EQ(eta(0.0, 0.3), 0.005);
  EXPECT_EQ(eta(4.999, 1.0), 0.005);
  EXPECT_EQ(eta(5.0, 1.0), 0.0);
  EXPECT_EQ(eta(9.5, 0.5), 0.0);
}

TEST(Expression, BowlParaboloid) {
  const Expression z_b("-0.1*(1 - ((x-2)^2 + (y-2)^2))", origin);
  EXPECT_DOUBLE_EQ(z_b(2.0, 2.0), -0.1);   // the bottom of the bowl
  EXPECT_NEAR(z_b(3.0, 2.0), 0.0, 1e-15);  // its rim, at radius 1 m
  EXPECT_DOUBLE_EQ(z_b(0.0, 0.0), -0.1 * (1.0 - 8.0));
  EXPECT_DOUBLE_EQ(z_b(2.5, 1.5), -0.1 * (1.0 - 0.5));
}

TEST(Expression, CopiesShareTheFormula) {
  const Expression a("x*y", origin);
  const Expression b = a;  // NOLINT(performance-unnecessary-copy-initialization): the point
  EXPECT_EQ(b.text(), "x*y");
  EXPECT_EQ(a(2.0, 3.0), 6.0);
  EXPECT_EQ(b(4.0, 0.5), 2.0);
  EXPECT_EQ(a(1.0, 1.0), 1.0);
}

TEST(ExpressionError, SyntaxErrorNamesTheOriginAndThePosition) {
  EXPECT_EQ(error_of([] { Expression("x + * 2", origin); }),
            "case.yaml:12: flow.initial.eta: syntax error in 'x + * 2' at character 5 ('* 2'): "
            "Unexpected operator \"*\"");
  EXPECT_EQ(error_of([] { Expression("3x", origin); }),
            "case.yaml:12: flow.initial.eta: syntax error in '3x' at character 2 ('x'): "
            "Unexpected variable \"x\"");
  EXPECT_EQ(error_of([] { Expression("sin(x", origin); }),
            "case.yaml:12: flow.initial.eta: syntax error at the end of 'sin(x': Missing "
            "parenthesis");
  EXPECT_EQ(error_of([] { Expression("x < 5 ? 1", origin); }),
            "case.yaml:12: flow.initial.eta: syntax error in 'x < 5 ? 1': If-then-else operator "
            "is missing an else clause");
  EXPECT_EQ(error_of([] { Expression("  ", origin); }),
            "case.yaml:12: flow.initial.eta: expected a formula in x and y, got an empty text");
}

// A formula longer than muParser takes is refused as such (not as a syntax error), and long
// formulas are quoted by their start and length: the message stays a line.
TEST(ExpressionError, LongFormulasAreNamedShort) {
  std::string long_sum = "x";
  while (long_sum.size() < 50000) long_sum += " + 1";
  EXPECT_EQ(error_of([&] { Expression(long_sum, origin); }),
            "case.yaml:12: flow.initial.eta: the formula '" + long_sum.substr(0, 100) + "... (" +
                std::to_string(long_sum.size()) +
                " characters)' is longer than the 19999 characters a formula may hold "
                "(the limit of muParser, which reads it): give the field as a raster or a table "
                "instead");
  std::string bad = long_sum.substr(0, 5000) + " + * 2";  // within the limit, wrong at its end
  const std::string message = error_of([&] { Expression(bad, origin); });
  EXPECT_LT(message.size(), 300u) << message;
  EXPECT_EQ(message, "case.yaml:12: flow.initial.eta: syntax error in '" + bad.substr(0, 100) +
                         "... (5006 characters)' at character 5004 ('* 2'): Unexpected operator "
                         "\"*\"");
}

TEST(ExpressionError, UnknownVariablesAreNamed) {
  EXPECT_EQ(error_of([] { Expression("x + t", origin); }),
            "case.yaml:12: flow.initial.eta: unknown variable 't' in 'x + t'; a formula may use "
            "only x and y [m]");
  EXPECT_EQ(error_of([] { Expression("z*x + h", origin); }),
            "case.yaml:12: flow.initial.eta: unknown variables 'h', 'z' in 'z*x + h'; a formula "
            "may use only x and y [m]");
}

TEST(ExpressionError, NonFiniteValueNamesThePoint) {
  const Expression e("1/x", origin);
  EXPECT_EQ(e(4.0, 1.0), 0.25);
  EXPECT_EQ(error_of([&] { e(0.0, 1.5); }),
            "case.yaml:12: flow.initial.eta: '1/x' is not finite at (x, y) = (0, 1.5) m: its "
            "value is inf");
  EXPECT_EQ(error_of([] { Expression("sqrt(x)", origin)(-1.0, 2.0); }),
            "case.yaml:12: flow.initial.eta: 'sqrt(x)' is not finite at (x, y) = (-1, 2) m: its "
            "value is nan");
}

}  // namespace
}  // namespace flotsam
