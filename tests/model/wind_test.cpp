#include "model/wind.hpp"

#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "model/lsystem/deriver.hpp"
#include "model/lsystem/parser.hpp"
#include "model/lsystem/turtle.hpp"

namespace eco {
namespace {

// A small L-system tree: a trunk with two orders of branches and leaves.
TreeSkeleton restTree() {
  const LSystem s = parseLSystem(
      "SYSTEM\nDECLARATIONS\n  ANGLE 35\n  PIPE_MODEL\nAXIOM\n  F(2)A\nRULES\n"
      "  A -> F[&A~]/(120)[&A~]/(120)A\nEND.\n",
      "wind.lsys");
  DeriveOptions options;
  options.iterations = 4;
  return interpretTree(s, derive(s, options));
}

float maxDistance(const TreeSkeleton& a, const TreeSkeleton& b) {
  float most = 0.0f;
  for (std::size_t i = 0; i < a.segments.size(); ++i)
    most = std::max(most, glm::length(a.segments[i].end() - b.segments[i].end()));
  return most;
}

TEST(Wind, CalmLeavesTheTreeAsItIs) {
  const TreeSkeleton rest = restTree();
  TreeSkeleton calm = rest;
  Wind wind;
  EXPECT_TRUE(wind.calm());
  applyWind(calm, wind);
  EXPECT_EQ(maxDistance(rest, calm), 0.0f);
  wind.undirected_ws = 5.0;  // k_f = 1: stiff, no sway (EcoMod's formula)
  EXPECT_TRUE(wind.calm());
}

TEST(Wind, BranchesKeepTheirLengthAndStayAttached) {
  TreeSkeleton tree = restTree();
  const TreeSkeleton rest = tree;
  Wind wind;
  wind.undirected_ws = 4.0;
  wind.flexibility = 0.3;
  wind.directed_wg = 8.0;
  wind.direction = {1.0, 0.0, 0.0};
  wind.time = 1.0;
  applyWind(tree, wind);
  EXPECT_GT(maxDistance(rest, tree), 0.1f);
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const BranchSegment& s = tree.segments[i];
    EXPECT_FLOAT_EQ(s.length_m, rest.segments[i].length_m);
    EXPECT_NEAR(glm::determinant(s.frame), 1.0f, 1e-4f);
    if (s.parent >= 0) {  // the turtle starts every branch at its parent's end
      const BranchSegment& parent = tree.segments[static_cast<std::size_t>(s.parent)];
      EXPECT_LT(glm::length(s.start - parent.end()), 1e-4f);
    }
  }
  for (const Leaf& leaf : tree.leaves) {
    const BranchSegment& s = tree.segments[static_cast<std::size_t>(leaf.segment)];
    EXPECT_LT(glm::length(leaf.position - s.end()), 1e-4f);  // leaves move with their twig
    EXPECT_NEAR(glm::length(leaf.direction), 1.0f, 1e-4f);
  }
}

TEST(Wind, DirectedWindLeansTheCrownDownwind) {
  TreeSkeleton tree = restTree();
  const TreeSkeleton rest = tree;
  Wind wind;
  wind.directed_wg = 10.0;
  wind.direction = {1.0, 0.0, 0.0};
  applyWind(tree, wind);
  double shift = 0.0;
  for (std::size_t i = 0; i < tree.segments.size(); ++i)
    shift += tree.segments[i].end().x - rest.segments[i].end().x;
  EXPECT_GT(shift / static_cast<double>(tree.segments.size()), 0.05);
}

TEST(Wind, SwayRepeatsEveryPeriod) {
  Wind wind;
  wind.undirected_ws = 3.0;
  wind.flexibility = 0.5;
  wind.time = 0.7;
  TreeSkeleton a = restTree(), b = restTree(), c = restTree();
  applyWind(a, wind);
  wind.time += 2.0 * std::numbers::pi;
  applyWind(b, wind);
  wind.time += 1.5;
  applyWind(c, wind);
  EXPECT_LT(maxDistance(a, b), 1e-4f);
  EXPECT_GT(maxDistance(a, c), 0.05f);
}

}  // namespace
}  // namespace eco
