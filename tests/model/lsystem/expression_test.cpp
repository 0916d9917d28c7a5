#include "model/lsystem/expression.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "model/lsystem/random.hpp"

namespace eco {
namespace {

struct Compiled {
  std::vector<std::string> slots{"x", "y"};
  std::vector<RandomVariable> variables{{"p", false, Distribution::Constant, 0.25, 0.0}};
  std::vector<std::pair<std::string, double>> defines{{"r1", 0.9}};

  Expression compile(const std::string& text, std::uint32_t* occurrence = nullptr) {
    TextCursor cursor(text, "test.lsys", 3);
    ExpressionScope scope{&slots, &variables, &defines, occurrence};
    Expression e = parseExpression(cursor, scope);
    EXPECT_TRUE(cursor.atEnd() || cursor.peek() == ',' || cursor.peek() == ')' ||
                cursor.peek() == '-')
        << text;
    return e;
  }
  double eval(const std::string& text, double x = 2.0, double y = 3.0) {
    const double values[] = {x, y};
    const VariableDeviates deviates(variables, 1);
    EvalEnv env{values, 4.0, 10.0, &deviates};
    return evaluate(compile(text), env);
  }
};

TEST(LSystemExpression, ArithmeticFollowsCPrecedenceWithPowerAboveUnaryMinus) {
  Compiled c;
  EXPECT_DOUBLE_EQ(c.eval("1 + 2 * 3"), 7.0);
  EXPECT_DOUBLE_EQ(c.eval("(1 + 2) * 3"), 9.0);
  EXPECT_DOUBLE_EQ(c.eval("10 - 4 - 3"), 3.0);  // left-associative
  EXPECT_DOUBLE_EQ(c.eval("8 / 4 / 2"), 1.0);
  EXPECT_DOUBLE_EQ(c.eval("2 ^ 3 ^ 2"), 512.0);  // right-associative
  EXPECT_DOUBLE_EQ(c.eval("-2 ^ 2"), -4.0);
  EXPECT_DOUBLE_EQ(c.eval("2 ^ -1"), 0.5);
  EXPECT_DOUBLE_EQ(c.eval("x * y + x"), 8.0);
  EXPECT_DOUBLE_EQ(c.eval("1.5e2"), 150.0);
}

TEST(LSystemExpression, RelationalAndLogicalOperatorsGiveOneOrZero) {
  Compiled c;
  EXPECT_EQ(c.eval("x < y"), 1.0);
  EXPECT_EQ(c.eval("x >= y"), 0.0);
  EXPECT_EQ(c.eval("x <= 2 && y > 2"), 1.0);
  EXPECT_EQ(c.eval("x == 3 || y != 3"), 0.0);
  EXPECT_EQ(c.eval("!(x == 2)"), 0.0);
  EXPECT_EQ(c.eval("NumIt = 4"), 1.0);  // Green writes NumIt = MaxIt
  EXPECT_EQ(c.eval("NumIt == MaxIt"), 0.0);
  EXPECT_EQ(c.eval("1 + 1 < 3 == 1"), 1.0);  // relational binds tighter than equality
}

TEST(LSystemExpression, FunctionsConstantsDefinesAndVariables) {
  Compiled c;
  EXPECT_NEAR(c.eval("sin(pi / 2)"), 1.0, 1e-12);
  EXPECT_NEAR(c.eval("cos(0) + tan(0)"), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(c.eval("sqrt(16) + abs(-2) + floor(2.7) + ceil(2.1)"), 11.0);
  EXPECT_DOUBLE_EQ(c.eval("min(x, y) + max(x, y)"), 5.0);
  EXPECT_DOUBLE_EQ(c.eval("pow(2, 10)"), 1024.0);
  EXPECT_NEAR(c.eval("exp(log(5))"), 5.0, 1e-12);
  EXPECT_DOUBLE_EQ(c.eval("clamp(7, 0, 5)"), 5.0);
  EXPECT_DOUBLE_EQ(c.eval("atan2(1, 1) * 4"), std::numbers::pi);
  EXPECT_DOUBLE_EQ(c.eval("r1 * 10"), 9.0);
  EXPECT_DOUBLE_EQ(c.eval("p * 4"), 1.0);
}

TEST(LSystemExpression, ConstantExpressionsFoldToOneInstruction) {
  Compiled c;
  EXPECT_TRUE(c.compile("2 * r1 + sqrt(4)").isConstant());
  EXPECT_DOUBLE_EQ(c.compile("2 * r1 + sqrt(4)").code[0].value, 3.8);
  EXPECT_FALSE(c.compile("x + 1").isConstant());
  EXPECT_FALSE(c.compile("p").isConstant());
  EXPECT_TRUE(c.compile("p").usesRandom());
}

TEST(LSystemExpression, SuccessorOccurrencesOfAVariableAreNumberedApart) {
  Compiled c;
  std::uint32_t next = 1;
  Expression e = c.compile("p + p", &next);
  EXPECT_EQ(next, 3u);
  EXPECT_EQ(e.code[0].occurrence, 1u);
  EXPECT_EQ(e.code[1].occurrence, 2u);
  Expression condition = c.compile("p + p");
  EXPECT_EQ(condition.code[0].occurrence, 0u);  // matching: one deviate per variable
  EXPECT_EQ(condition.code[1].occurrence, 0u);
}

TEST(LSystemExpression, StopsBeforeTheArrowOfAProduction) {
  Compiled c;
  TextCursor cursor("x>1 -> B", "test.lsys", 1);
  ExpressionScope scope{&c.slots, &c.variables, &c.defines, nullptr};
  parseExpression(cursor, scope);
  cursor.skipSpace();
  EXPECT_EQ(cursor.text().substr(cursor.position()), "-> B");
}

void expectError(const std::string& text, const std::string& expected) {
  Compiled c;
  try {
    c.compile(text);
    FAIL() << "no error for " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), expected);
  }
}

TEST(LSystemExpression, ErrorsNameLineAndColumn) {
  expectError("1 + z",
              "test.lsys:3:5: unknown name 'z' (not a parameter of the predecessor, "
              "a random variable, a DEFINE, NumIt, MaxIt or pi)");
  expectError("(1 + 2", "test.lsys:3:7: expected ')' to close '(' but the line ends");
  expectError("sin(1, 2)", "test.lsys:3:1: sin takes 1 argument, not 2");
  expectError("foo(1)", "test.lsys:3:1: unknown function 'foo' (known: " + functionList() + ")");
  expectError("2 * * 3", "test.lsys:3:5: expected a value, found '*'");
  expectError("", "test.lsys:3:1: expected an expression");
  // Hostile nesting is an error, not a stack overflow.
  const std::string deep = std::string(100000, '(') + "1" + std::string(100000, ')');
  expectError(deep, "test.lsys:3:201: expression nested too deeply");
  expectError(std::string(100000, '-') + "1", "test.lsys:3:201: expression nested too deeply");
}

}  // namespace
}  // namespace eco
