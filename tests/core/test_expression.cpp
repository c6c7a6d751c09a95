// The density expression language: values (precedence, functions, variables) and hostile
// input from share links (length, nesting, size, names, characters) refused with a message.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/density/expression.h"
#include "core/util/angles.h"
#include "core/util/error.h"
#include "input_error_message.h"

namespace ff {
namespace {

double eval(const std::string& text, ExprInputs in = {}) { return Expression::parse(text).evaluate(in); }

// The InputError message for `text`, or "" when it parses.
std::string parse_error(const std::string& text) {
  return test::input_error_message([&] { Expression::parse(text); });
}

TEST(Expression, ArithmeticAndPrecedence) {
  EXPECT_DOUBLE_EQ(eval("1 + 2 * 3"), 7.0);
  EXPECT_DOUBLE_EQ(eval("(1 + 2) * 3"), 9.0);
  EXPECT_DOUBLE_EQ(eval("8 / 4 / 2"), 1.0);    // left associative
  EXPECT_DOUBLE_EQ(eval("10 - 4 - 3"), 3.0);   // left associative
  EXPECT_DOUBLE_EQ(eval("2 ^ 3 ^ 2"), 512.0);  // right associative
  EXPECT_DOUBLE_EQ(eval("-2 ^ 2"), -4.0);      // ^ binds tighter than unary minus
  EXPECT_DOUBLE_EQ(eval("2 ^ -1"), 0.5);
  EXPECT_DOUBLE_EQ(eval("--3"), 3.0);
  EXPECT_DOUBLE_EQ(eval("+3 - -2"), 5.0);
  EXPECT_DOUBLE_EQ(eval("7 % 3"), 1.0);
  EXPECT_DOUBLE_EQ(eval("-1 % 3"), 2.0);  // floored
  EXPECT_DOUBLE_EQ(eval("1.5e2 + .5"), 150.5);
  EXPECT_DOUBLE_EQ(eval("2 * pi"), 2.0 * kPi);
  EXPECT_DOUBLE_EQ(eval("e"), std::exp(1.0));
}

TEST(Expression, ComparisonsLogicAndConditionals) {
  EXPECT_DOUBLE_EQ(eval("1 < 2"), 1.0);
  EXPECT_DOUBLE_EQ(eval("2 <= 1"), 0.0);
  EXPECT_DOUBLE_EQ(eval("1 + 1 == 2"), 1.0);
  EXPECT_DOUBLE_EQ(eval("1 != 1"), 0.0);
  EXPECT_DOUBLE_EQ(eval("1 < 2 && 3 > 4"), 0.0);
  EXPECT_DOUBLE_EQ(eval("1 < 2 || 3 > 4"), 1.0);
  EXPECT_DOUBLE_EQ(eval("!0 + !5"), 1.0);
  EXPECT_DOUBLE_EQ(eval("1 < 2 ? 10 : 20"), 10.0);
  EXPECT_DOUBLE_EQ(eval("0 ? 1 : 0 ? 2 : 3"), 3.0);  // right associative
  EXPECT_DOUBLE_EQ(eval("1 + (0 ? 5 : 6)"), 7.0);
  EXPECT_DOUBLE_EQ(eval("if(0, 1, 2)"), 2.0);
  EXPECT_DOUBLE_EQ(eval("if(1, 5, log(0))"), 5.0);  // the other branch may be anything
}

TEST(Expression, Functions) {
  EXPECT_NEAR(eval("sin(pi / 2) + cos(0) + tan(0)"), 2.0, 1e-15);
  EXPECT_NEAR(eval("atan2(1, 1)"), kPi / 4, 1e-15);
  EXPECT_DOUBLE_EQ(eval("sqrt(16) + abs(-2) + exp(0) + log(e) + log10(100)"), 10.0);
  EXPECT_DOUBLE_EQ(eval("pow(2, 10)"), 1024.0);
  EXPECT_DOUBLE_EQ(eval("min(3, 1, 2) + max(3, 9, 2)"), 10.0);
  EXPECT_DOUBLE_EQ(eval("clamp(5, 0, 2) + clamp(-1, 0, 2)"), 2.0);
  EXPECT_DOUBLE_EQ(eval("smoothstep(0, 1, 0.5)"), 0.5);
  EXPECT_DOUBLE_EQ(eval("smoothstep(0, 1, 2) + smoothstep(0, 1, -1)"), 1.0);
  EXPECT_DOUBLE_EQ(eval("floor(2.7) + ceil(2.2) + round(2.5)"), 8.0);
  EXPECT_DOUBLE_EQ(eval("mod(7, 4) + step(0.5, 0.7) + sign(-3)"), 3.0);
  EXPECT_DOUBLE_EQ(eval("mix(2, 4, 0.25)"), 2.5);
  EXPECT_TRUE(std::isinf(eval("1 / 0")));
  EXPECT_TRUE(std::isnan(eval("sqrt(-1)")));
}

TEST(Expression, Variables) {
  ExprInputs in{};
  for (int i = 0; i < kNumExprVars; ++i) in[static_cast<size_t>(i)] = i + 1.0;
  EXPECT_DOUBLE_EQ(eval("x + 10 * y + 100 * z", in), 321.0);
  EXPECT_DOUBLE_EQ(eval("u * v * w", in), 4.0 * 5 * 6);
  EXPECT_DOUBLE_EQ(eval("nx + ny + nz", in), 7.0 + 8 + 9);
  EXPECT_DOUBLE_EQ(eval("k1 - k2 + H * K + curv", in), 10.0 - 11 + 12 * 13 + 14);
  const Expression e = Expression::parse("1 + u");
  EXPECT_TRUE(e.uses(ExprVar::U));
  EXPECT_FALSE(e.uses(ExprVar::X));
  EXPECT_FALSE(e.uses_curvature());
  EXPECT_TRUE(Expression::parse("1 + curv").uses_curvature());
}

TEST(Expression, PresetsParseAndArePositive) {
  ExprInputs in{};
  for (const DensityPreset& p : kDensityPresets) {
    const Expression e = Expression::parse(p.expression);
    for (double t : {0.0, 0.3, 0.5, 1.0}) {
      in[static_cast<size_t>(ExprVar::U)] = in[static_cast<size_t>(ExprVar::V)] = t;
      in[static_cast<size_t>(ExprVar::Curv)] = 10 * t;
      in[static_cast<size_t>(ExprVar::Border)] = t;
      EXPECT_GE(e.evaluate(in), 1.0) << p.name;
    }
  }
}

// Each hostile input is refused with a message containing `needle`.
void expect_refused(const std::string& text, const std::string& needle) {
  const std::string message = parse_error(text);
  EXPECT_NE(message.find(needle), std::string::npos)
      << "input '" << text.substr(0, 60) << "' gave '" << message << "', wanted '" << needle << "'";
}

TEST(Expression, HostileInputsAreRefusedWithClearMessages) {
  expect_refused(std::string(10000, '1'), "too long (10000 characters; at most 4096)");
  expect_refused(std::string(1000, '(') + "1" + std::string(1000, ')'), "nested too deeply at column 65");
  expect_refused(std::string(1000, '-') + "1", "nested too deeply");
  std::string tower = "2";
  for (int i = 0; i < 500; ++i) tower += "^2";
  expect_refused(tower, "nested too deeply");
  std::string sum = "1";
  for (int i = 0; i < 1500; ++i) sum += "+1";  // 3001 terms, flat: the size limit, not depth
  expect_refused(sum, "too many terms (more than 2000)");
  expect_refused("alert(1)", "unknown name 'alert' at column 1");
  expect_refused("constructor", "unknown name 'constructor' at column 1");
  expect_refused("x + __proto__", "unknown name '__proto__' at column 5");
  expect_refused("window.location", "unexpected character '.' at column 7");
  expect_refused("x;y", "unexpected character ';' at column 2");
  expect_refused("\"", "unexpected character '\"' at column 1");
  expect_refused("'1'", "unexpected character ''' at column 1");
  expect_refused("`${x}`", "unexpected character '`' at column 1");
  expect_refused("\\u0000", "unexpected character '\\' at column 1");
  expect_refused(std::string("1 +\0 2", 6), "control character at column 4");
  expect_refused("1 + \xC3\xA9", "non-ASCII character at column 5");
  expect_refused("x = 1", "'=' at column 3");
  expect_refused("sin(1, 2)", "calls 'sin' at column 1 with 2 arguments (it takes 1)");
  expect_refused("clamp(1)", "calls 'clamp' at column 1 with 1 argument (it takes 3)");
  expect_refused("min()", "it takes 2 to 16");
  expect_refused("x(1)", "'x' at column 1, which is not a function");
  expect_refused("sin", "function 'sin' without '('");
  expect_refused("1 2", "unexpected '2' at column 3");
  expect_refused("(1 + 2", "expected ')' at column 7");
  expect_refused("1 +", "ends early");
  expect_refused("1 ? 2", "expected ':'");
  expect_refused("", "is empty");
  expect_refused("   ", "is empty");
  expect_refused("1e999", "number too large at column 1");
  expect_refused(std::string(5000, 'a'), "too long");
  // Exactly at the limits is fine.
  EXPECT_EQ(parse_error(std::string(63, '(') + "1" + std::string(63, ')')), "");
  EXPECT_EQ(parse_error("1" + std::string(4094, ' ')), "");
}

}  // namespace
}  // namespace ff
