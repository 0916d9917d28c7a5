#include "model/lsystem/parser.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace eco {
namespace {

const char* kGreen = R"(SYSTEM Green example
DECLARATIONS
  CONTINUOUS p UNIFORM(0,1)
  IGNORE + - F
AXIOM
  A(1)B(3)A(5)
RULES
  A(x): p<0.4 -> A(x+1)
  A(x): p>0.4 -> B(x-1)
  A(x) < B(y) > A(z) : y<4 -> B(x+z)[A(y)]
END.
)";

TEST(LSystemParser, ReadsGreensExample) {
  const LSystem s = parseLSystem(kGreen, "green.lsys");
  EXPECT_EQ(s.name, "Green example");
  ASSERT_EQ(s.variables.size(), 1u);
  EXPECT_EQ(s.variables[0].distribution, Distribution::Uniform);
  EXPECT_EQ(s.variables[0].b, 1.0);
  EXPECT_TRUE(s.ignored['+'] && s.ignored['-'] && s.ignored['F']);
  EXPECT_FALSE(s.ignored['A']);
  ASSERT_EQ(s.axiom.modules.size(), 3u);
  ASSERT_EQ(s.productions.size(), 3u);
  const Production& context = s.productions[2];
  EXPECT_EQ(context.line, 10);
  EXPECT_EQ(context.text, "A(x) < B(y) > A(z) : y<4 -> B(x+z)[A(y)]");
  ASSERT_EQ(context.left.size(), 1u);
  EXPECT_EQ(context.left[0].symbol, 'A');
  EXPECT_EQ(context.strict.symbol, 'B');
  ASSERT_EQ(context.right.size(), 1u);
  EXPECT_EQ(context.slotCount, 3);
  EXPECT_EQ(context.successor.modules.size(), 4u);
  EXPECT_TRUE(s.usesContext);
  EXPECT_EQ(s.rulesBySymbol['A'], (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(s.rulesBySymbol['B'], (std::vector<std::uint32_t>{2}));
}

TEST(LSystemParser, ReadsDeclarationsAndSections) {
  const LSystem s = parseLSystem(R"(# a comment line
SYSTEM
DECLARATIONS
  DISCRETE n POISSON(3)   # trailing comment
  DEFINE r 0.5
  DEFINE r2 r * 2
  ITERATIONS 7
  STEP 2
  ANGLE 22.5
  WIDTH 0.2
  WIDTH_SCALE 0.6
  LEAF_SIZE 0.3
  LEAF L K
  TROPISM 0 -1 0 0.25
  PIPE_MODEL
  UNIT 0.01
  PRUNE ELLIPSOID(0, 5, 0, 3, 5, 3)
  MAXMODULES 1000
AXIOM
  F(r2)
  A
RULES
  A -> F(r)[+A]
INTERPRETATION
  A -> ~
END
)",
                                 "d.lsys");
  EXPECT_EQ(s.iterations, 7);
  EXPECT_EQ(s.turtle.step, 2.0);
  EXPECT_EQ(s.turtle.angle_deg, 22.5);
  EXPECT_EQ(s.turtle.width, 0.2);
  EXPECT_EQ(s.turtle.widthScale, 0.6);
  EXPECT_EQ(s.turtle.leafSize, 0.3);
  EXPECT_EQ(s.turtle.tropism, glm::dvec3(0, -1, 0));
  EXPECT_EQ(s.turtle.tropismStrength, 0.25);
  EXPECT_TRUE(s.turtle.pipeModel);
  EXPECT_EQ(s.turtle.unit_m, 0.01);
  EXPECT_EQ(s.prune.shape, PruneShape::Ellipsoid);
  EXPECT_EQ(s.prune.extent, glm::dvec3(3, 5, 3));
  EXPECT_EQ(s.maxModules, 1000u);
  EXPECT_TRUE(s.leaves['L'] && s.leaves['K'] && s.leaves['~']);
  ASSERT_EQ(s.axiom.modules.size(), 2u);  // the axiom may span lines
  EXPECT_DOUBLE_EQ(s.axiom.modules[0].params[0].code[0].value, 1.0);
  EXPECT_TRUE(s.productions[0].successor.constant);
  EXPECT_EQ(s.interpretationsBySymbol['A'].size(), 1u);
}

TEST(LSystemParser, ControlAndInterrogationModules) {
  const LSystem s = parseLSystem(R"(SYSTEM
DECLARATIONS
  DISCRETE n POISSON(3)
AXIOM
  @Switch{A B C}@Pendulum{AB}@Repetition(n){F[+F]}?P@Prune
RULES
END.
)",
                                 "c.lsys");
  const auto& m = s.axiom.modules;
  ASSERT_EQ(m.size(), 5u);
  EXPECT_EQ(m[0].symbol, kSwitch);
  EXPECT_EQ(s.axiom.bodies[static_cast<std::size_t>(m[0].body)].modules.size(), 3u);
  EXPECT_EQ(m[1].symbol, kPendulum);
  EXPECT_DOUBLE_EQ(m[1].params[0].code[0].value, 1.0);  // forward first
  EXPECT_EQ(m[2].symbol, kRepetition);
  EXPECT_TRUE(m[2].params[0].usesRandom());
  EXPECT_EQ(m[3].symbol, kQueryPosition);
  EXPECT_EQ(m[3].params.size(), 3u);
  EXPECT_EQ(m[4].symbol, kPrune);
  EXPECT_TRUE(s.usesQueries);
  EXPECT_TRUE(s.usesPrune);
}

void expectError(const std::string& text, const std::string& expected) {
  try {
    parseLSystem(text, "bad.lsys");
    FAIL() << "no error for:\n" << text;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), expected);
  }
}

std::string withRules(const std::string& rules, const std::string& declarations = "") {
  return "SYSTEM\nDECLARATIONS\n" + declarations + "AXIOM\n  A\nRULES\n" + rules + "END.\n";
}

TEST(LSystemParser, SyntaxErrorsReportLineAndColumn) {
  expectError(withRules("  A(x -> B\n"),
              "bad.lsys:6:7: expected ')' to close the formal "
              "parameters, found '-'");
  expectError(withRules("  A -> B(1,\n"), "bad.lsys:6:12: expected an expression");
  expectError(withRules("  A B -> C\n"),
              "bad.lsys:6:3: the strict predecessor is one module; write contexts as lc < "
              "pred > rc");
  expectError(withRules("  A : x > 1 -> B\n"),
              "bad.lsys:6:7: unknown name 'x' (not a parameter of the predecessor, a random "
              "variable, a DEFINE, NumIt, MaxIt or pi)");
  expectError(withRules("  A -> [B\n"), "bad.lsys:6:8: '[' is never closed");
  expectError(withRules("  A -> B]\n"), "bad.lsys:6:9: ']' closes no '['");
  expectError(withRules("  A B\n"),
              "bad.lsys:6:3: the strict predecessor is one module; write "
              "contexts as lc < pred > rc");
  expectError(withRules("  A\n"), "bad.lsys:6:4: expected '->' but the line ends");
  expectError(withRules("  A(x,x) -> B\n"), "bad.lsys:6:7: formal parameter 'x' appears twice");
  expectError(withRules("  A -> @Loop{B}\n"),
              "bad.lsys:6:8: unknown control module '@Loop' (expected @Switch, @Pendulum, "
              "@Repetition or @Prune)");
  expectError(withRules("  A -> @Switch{B[C]}\n"),
              "bad.lsys:6:16: @Switch lists single modules: no brackets or control modules "
              "inside");
  expectError(withRules("  A -> ?Q\n"),
              "bad.lsys:6:8: an interrogation module is ?P, ?H, ?U or ?L");
  expectError(withRules("  [ -> F\n"), "bad.lsys:6:8: a bracket can only be rewritten as itself");
  expectError(withRules("", "  CONTINUOUS p UNIFORM(1, 0)\n"),
              "bad.lsys:3:16: UNIFORM(a, b) needs a <= b");
  expectError(withRules("", "  CONTINUOUS p CAUCHY(1)\n"),
              "bad.lsys:3:16: unknown distribution 'CAUCHY' (expected CONSTANT, UNIFORM, "
              "EXPONENTIAL, NORMAL, BINOMIAL or POISSON)");
  expectError(withRules("", "  FOO 1\n"),
              "bad.lsys:3:3: unknown declaration 'FOO' (expected CONTINUOUS, DISCRETE, IGNORE, "
              "DEFINE, ITERATIONS, STEP, ANGLE, WIDTH, WIDTH_SCALE, LEAF, LEAF_SIZE, TROPISM, "
              "PIPE_MODEL, UNIT, PRUNE or MAXMODULES)");
  expectError(withRules("", "  ITERATIONS 2.5\n"), "bad.lsys:3:14: expected an integer");
  expectError(withRules("", "  DEFINE p 1\n  DEFINE p 2\n"),
              "bad.lsys:4:10: 'p' is already defined");
  // Derivation recurses into control bodies: their nesting is bounded. The 33rd of 40
  // nested Repetitions (15 characters each, after "  A -> ") starts at column 488.
  std::string nested = "  A -> ";
  for (int k = 0; k < 40; ++k) nested += "@Repetition(1){";
  expectError(withRules(nested + "F" + std::string(40, '}') + "\n"),
              "bad.lsys:6:488: control modules nested more than 32 deep");
}

TEST(LSystemParser, SectionErrors) {
  expectError("", "bad.lsys:1:1: empty grammar: expected SYSTEM");
  expectError("AXIOM\n A\n", "bad.lsys:1:1: a grammar starts with SYSTEM");
  expectError("SYSTEM\nDECLARATIONS\n", "bad.lsys:3:1: missing AXIOM section");
  expectError("SYSTEM\nAXIOM\nRULES\nEND.\n", "bad.lsys:3:1: the AXIOM is empty");
  expectError("SYSTEM\nAXIOM\n A\nRULES\n A -> B\n", "bad.lsys:6:1: missing END.");
  expectError("SYSTEM\nAXIOM\n A\nEND.\nA\n", "bad.lsys:5:1: text after END.");
}

TEST(LSystemParser, MissingFileIsAnInputError) {
  EXPECT_THROW(loadLSystem("/nonexistent/grammar.lsys"), InputError);
}

}  // namespace
}  // namespace eco
