#include "model/lsystem/turtle.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "model/lsystem/deriver.hpp"
#include "model/lsystem/parser.hpp"

namespace eco {
namespace {

LSystem system(const std::string& axiom, const std::string& declarations = "",
               const std::string& rules = "") {
  return parseLSystem("SYSTEM\nDECLARATIONS\n" + declarations + "AXIOM\n" + axiom + "\nRULES\n" +
                          rules + "\nEND.\n",
                      "turtle.lsys");
}

TreeSkeleton interpretAxiom(const std::string& axiom, const std::string& declarations = "",
                            const std::string& rules = "", InterpretStats* stats = nullptr) {
  const LSystem s = system(axiom, declarations, rules);
  return interpretTree(s, instantiateAxiom(s, 1, 0), stats);
}

void expectNear(glm::vec3 a, glm::vec3 b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(LSystemTurtle, DrawsUpwardAndTurnsAboutItsAxes) {
  const TreeSkeleton t = interpretAxiom("F(2)+(90)F(1)-(90)&(90)F(1)", "WIDTH 0.2\n");
  ASSERT_EQ(t.segments.size(), 3u);
  expectNear(t.segments[0].start, {0, 0, 0});
  expectNear(t.segments[0].axis(), {0, 1, 0});
  EXPECT_FLOAT_EQ(t.segments[0].length_m, 2.0f);
  EXPECT_FLOAT_EQ(t.segments[0].startRadius_m, 0.1f);
  expectNear(t.segments[1].start, {0, 2, 0});
  expectNear(t.segments[1].axis(), {-1, 0, 0});  // + turns left, toward L = -x
  expectNear(t.segments[2].axis(), {0, 0, -1});  // & pitches down, away from U = +z
  expectNear(t.segments[2].end(), {-1, 2, -1});
  for (const BranchSegment& s : t.segments) {  // frames are rotations with y the axis
    EXPECT_NEAR(glm::determinant(s.frame), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(s.frame[0], s.frame[1]), 0.0f, 1e-5f);
  }
}

TEST(LSystemTurtle, RollAndTurnAroundKeepTheFrameRightHanded) {
  const LSystem s = system("F");
  Turtle turtle(s);
  const double angle = 90.0;
  turtle.apply('/', &angle, 1);
  turtle.apply('+', &angle, 1);
  const TurtleState& state = turtle.state();
  EXPECT_NEAR(glm::length(glm::cross(state.heading, state.left) - state.up), 0.0, 1e-12);
  turtle.apply('|', nullptr, 0);
  EXPECT_NEAR(
      glm::length(glm::cross(turtle.state().heading, turtle.state().left) - turtle.state().up), 0.0,
      1e-12);
  turtle.apply('$', nullptr, 0);
  EXPECT_NEAR(turtle.state().left.y, 0.0, 1e-12);  // $ levels L
}

TEST(LSystemTurtle, BranchesHaveParentsAndOneContinuation) {
  const TreeSkeleton t = interpretAxiom("F[+F][-F]F f F");
  ASSERT_EQ(t.segments.size(), 5u);
  EXPECT_EQ(t.segments[1].parent, 0);
  EXPECT_FALSE(t.segments[1].continuesParent);
  EXPECT_EQ(t.segments[2].parent, 0);
  EXPECT_FALSE(t.segments[2].continuesParent);
  EXPECT_EQ(t.segments[3].parent, 0);
  EXPECT_TRUE(t.segments[3].continuesParent);  // the main axis goes on after the brackets
  EXPECT_EQ(t.segments[4].parent, 3);
  EXPECT_FALSE(t.segments[4].continuesParent);  // f leaves a gap
  EXPECT_EQ(t.segments[1].gravelius, 1);
  EXPECT_EQ(t.segments[3].gravelius, 0);
  EXPECT_EQ(t.segments[0].strands, 3);  // tips below: two branches and the top
  EXPECT_EQ(t.segments[0].weibull, 2);  // Strahler order
  expectNear(t.segments[4].start, {0, 3, 0});
}

TEST(LSystemTurtle, WidthsJoinAndFollowThePipeModel) {
  const TreeSkeleton set = interpretAxiom("!(0.4)F!(0.2)F!F", "WIDTH_SCALE 0.5\n");
  EXPECT_FLOAT_EQ(set.segments[0].startRadius_m, 0.2f);
  EXPECT_FLOAT_EQ(set.segments[0].endRadius_m, 0.1f);     // meets the next tube
  EXPECT_FLOAT_EQ(set.segments[2].startRadius_m, 0.05f);  // ! without a parameter scales
  const TreeSkeleton pipe = interpretAxiom("F[+F][-F][&F]F", "WIDTH 0.1\nPIPE_MODEL\n");
  EXPECT_FLOAT_EQ(pipe.segments[0].startRadius_m, 0.05f * 2.0f);  // four tips: sqrt(4)
  EXPECT_FLOAT_EQ(pipe.segments[1].startRadius_m, 0.05f);
}

TEST(LSystemTurtle, LeavesSitOnTheirBranchAndFaceUp) {
  InterpretStats stats;
  const TreeSkeleton t =
      interpretAxiom("~F(2)[+(90)L(0.5)]~", "LEAF L\nLEAF_SIZE 0.3\n", "", &stats);
  ASSERT_EQ(t.leaves.size(), 2u);
  EXPECT_EQ(stats.droppedLeaves, 1u);  // the first ~ has no wood to sit on
  EXPECT_EQ(t.leaves[0].segment, 0);
  EXPECT_FLOAT_EQ(t.leaves[0].size_m, 0.5f);
  expectNear(t.leaves[0].direction, {-1, 0, 0});
  expectNear(t.leaves[0].normal, {0, 0, 1});
  EXPECT_FLOAT_EQ(t.leaves[1].size_m, 0.3f);
  expectNear(t.leaves[1].position, {0, 2, 0});
}

TEST(LSystemTurtle, APolygonBecomesOneLeafAlongItsLength) {
  const TreeSkeleton t = interpretAxiom("F{.+(30)f(1).-(60)f(1).-(120)f(1).}");
  ASSERT_EQ(t.segments.size(), 1u);  // F inside { } draws no wood
  ASSERT_EQ(t.leaves.size(), 1u);
  EXPECT_GT(t.leaves[0].size_m, 1.0f);
  EXPECT_LT(t.leaves[0].size_m, 2.0f);
  expectNear(t.leaves[0].position, {0, 1, 0});
}

TEST(LSystemTurtle, TropismBendsTheHeadingTowardItsVector) {
  const TreeSkeleton t = interpretAxiom("+(90)FFFFFFFFFF", "TROPISM 0 -1 0 0.3\n");
  ASSERT_EQ(t.segments.size(), 10u);
  for (std::size_t i = 1; i < t.segments.size(); ++i)
    EXPECT_LT(t.segments[i].axis().y, t.segments[i - 1].axis().y);  // droops ever more
  EXPECT_LT(t.segments.back().axis().y, -0.5f);
  const TreeSkeleton upright = interpretAxiom("FFF", "TROPISM 0 -1 0 0.3\n");
  expectNear(upright.segments.back().axis(), {0, 1, 0});  // parallel: H x T = 0
}

TEST(LSystemTurtle, InterpretationRulesDrawModulesOnce) {
  const TreeSkeleton t = interpretAxiom("A(2)B", "", "", nullptr);
  EXPECT_TRUE(t.segments.empty());  // A and B mean nothing to the turtle
  const LSystem mapped = parseLSystem(
      "SYSTEM\nAXIOM\nA(2)B\nRULES\nINTERPRETATION\nA(l) -> F(l)B\nB -> [+F]\nEND.\n", "m");
  const TreeSkeleton drawn = interpretTree(mapped, instantiateAxiom(mapped, 1, 0));
  ASSERT_EQ(drawn.segments.size(), 2u);  // the B that A makes is not mapped again
  EXPECT_FLOAT_EQ(drawn.segments[0].length_m, 2.0f);
  EXPECT_EQ(drawn.segments[1].parent, 0);
}

TEST(LSystemTurtle, PruningCutsBranchesAtTheVolume) {
  for (const char* shape : {"ELLIPSOID(0, 6, 0, 3, 6, 3)", "BOX(-3, 0, -3, 3, 12, 3)"}) {
    const LSystem bush = parseLSystem(std::string("SYSTEM\nDECLARATIONS\n  PRUNE ") + shape +
                                          "\n  ANGLE 30\nAXIOM\nA\nRULES\n"
                                          "A -> F[&A]/(120)[&A]/(120)A\nEND.\n",
                                      "bush.lsys");
    DeriveOptions options;
    options.iterations = 14;
    const TreeSkeleton t = interpretTree(bush, derive(bush, options));
    ASSERT_GT(t.segments.size(), 50u) << shape;
    float top = 0.0f;
    for (const BranchSegment& s : t.segments) {
      EXPECT_TRUE(bush.prune.contains(glm::dvec3(s.end()) * 0.9999)) << shape;
      top = std::max(top, s.end().y);
    }
    EXPECT_GT(top, 10.0f) << shape;  // it fills the volume up to its top
  }
}

TEST(LSystemTurtle, NonFiniteParametersAreAnInputError) {
  EXPECT_THROW(interpretAxiom("F(1/0)"), InputError);
  EXPECT_THROW(interpretAxiom("F+(sqrt(-1))F"), InputError);
  EXPECT_NO_THROW(interpretAxiom("A(1/0)F"));  // modules the turtle ignores may hold anything
}

TEST(LSystemTurtle, CutsKeepTheStringBalanced) {
  LSystem s = system("F[+F(10)F]F(20)", "PRUNE BOX(-5, 0, -5, 5, 8, 5)\n");
  ModuleString string = instantiateAxiom(s, 1, 0);
  EXPECT_TRUE(applyEnvironment(s, string));
  EXPECT_EQ(toString(string), "F[+]");
  EXPECT_FALSE(applyEnvironment(s, string));
}

}  // namespace
}  // namespace eco
