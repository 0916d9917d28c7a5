#include "model/design/hint.hpp"

#include <gtest/gtest.h>

#include "model/tree_generator.hpp"
#include "test_support.hpp"

namespace eco {

TEST(Hint, APointInfluencesTheOpenIntervalBetweenItsNeighbours) {
  const Polyline line({{0.0, 1.0}, {7.5, 0.45}, {15.0, 1.0}});
  const HintInterval middle = pointInfluence(LocalGraph::MinLenG, line, 1);
  EXPECT_FALSE(middle.contains(0.0));  // the neighbours keep their values
  EXPECT_TRUE(middle.contains(1.0));
  EXPECT_TRUE(middle.contains(14.0));
  EXPECT_FALSE(middle.contains(15.0));
  const HintInterval first = pointInfluence(LocalGraph::MinLenG, line, 0);
  EXPECT_TRUE(first.contains(-1.0));
  EXPECT_TRUE(first.contains(7.0));
  EXPECT_FALSE(first.contains(7.5));
  const HintInterval last = pointInfluence(LocalGraph::MinLenG, line, 2);
  EXPECT_TRUE(last.contains(40.0));  // beyond the last point the graph is its value
  EXPECT_FALSE(last.contains(7.5));
  const HintInterval span = segmentSpan(LocalGraph::MinLenG, line, 0);
  EXPECT_TRUE(span.contains(0.0));
  EXPECT_TRUE(span.contains(7.5));
  EXPECT_FALSE(span.contains(8.0));
}

TEST(Hint, HintedSegmentsAreExactlyThoseWhoseOrderLiesInTheInterval) {
  const Species beech = test::loadNamed("beech");
  const TreeSkeleton tree = buildTree(beech, {});
  const HintInterval g = {LocalGraph::AlphaG, 1.5, 3.0, true};
  const std::vector<std::int32_t> hinted = hintedSegments(tree, g);
  std::size_t expected = 0;
  for (const BranchSegment& s : tree.segments) expected += s.gravelius == 2 || s.gravelius == 3;
  EXPECT_EQ(hinted.size(), expected);
  ASSERT_GT(hinted.size(), 0u);
  for (std::int32_t i : hinted)
    EXPECT_TRUE(tree.segments[i].gravelius == 2 || tree.segments[i].gravelius == 3);
  EXPECT_TRUE(std::is_sorted(hinted.begin(), hinted.end()));
  // A *_w graph hints by Weibull order.
  const HintInterval w = pointInfluence(LocalGraph::KsW, Polyline({{0, 1}, {4, 1}, {50, 1}}), 0);
  for (std::int32_t i : hintedSegments(tree, w)) EXPECT_LT(tree.segments[i].weibull, 4);
  EXPECT_EQ(hintedSegments(tree, wholeGraph(LocalGraph::KsW)).size(), tree.segments.size());
}

TEST(Hint, SleevesWrapEachHintedSegmentOutsideItsWood) {
  const Species beech = test::loadNamed("beech");
  const TreeSkeleton tree = buildTree(beech, {});
  const std::vector<std::int32_t> trunk = {0};
  const MeshPart sleeves = hintSleeves(tree, trunk);
  EXPECT_EQ(sleeves.triangleCount(), 12u);
  const BranchSegment& s = tree.segments[0];
  for (std::size_t v = 0; v < sleeves.positions.size(); ++v) {
    const glm::vec3 offset = sleeves.positions[v] - s.start;
    const glm::vec3 radial = offset - glm::dot(offset, s.axis()) * s.axis();
    EXPECT_GT(glm::length(radial), s.startRadius_m);
    EXPECT_GT(glm::dot(radial, sleeves.normals[v]), 0.0f);  // normals point outward
  }
  // Counter-clockwise seen from outside: each face's normal points away from the axis.
  for (std::size_t t = 0; t < sleeves.indices.size(); t += 3) {
    const glm::vec3 a = sleeves.positions[sleeves.indices[t]],
                    b = sleeves.positions[sleeves.indices[t + 1]],
                    c = sleeves.positions[sleeves.indices[t + 2]];
    const glm::vec3 face = glm::cross(b - a, c - a);
    const glm::vec3 centre = (a + b + c) / 3.0f - s.start;
    const glm::vec3 radial = centre - glm::dot(centre, s.axis()) * s.axis();
    EXPECT_GT(glm::dot(face, radial), 0.0f);
  }
}

}  // namespace eco
