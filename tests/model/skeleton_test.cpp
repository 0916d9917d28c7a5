#include "model/skeleton.hpp"

#include <gtest/gtest.h>

namespace eco {

TEST(Skeleton, MeasureHandBuiltTree) {
  TreeSkeleton tree;
  BranchSegment trunk;
  trunk.length_m = 4.0f;
  trunk.startRadius_m = 0.2f;
  trunk.strands = 2;
  tree.segments.push_back(trunk);
  BranchSegment side;
  side.start = trunk.end();
  side.frame = glm::mat3(glm::vec3(0, -1, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1));  // axis +x
  side.length_m = 3.0f;
  side.parent = 0;
  side.gravelius = 1;
  side.weibull = 1;
  tree.segments.push_back(side);
  Leaf leaf;
  leaf.position = glm::vec3(0, 4, 0);
  leaf.direction = glm::vec3(0, 1, 0);
  leaf.size_m = 0.5f;
  tree.leaves.push_back(leaf);

  SkeletonMeasures m = measure(tree);
  EXPECT_EQ(m.segments, 2u);
  EXPECT_EQ(m.terminalSegments, 1u);
  EXPECT_EQ(m.maxGravelius, 1);
  EXPECT_EQ(m.maxWeibull, 1);
  EXPECT_DOUBLE_EQ(m.height_m, 4.5);       // the leaf tip
  EXPECT_DOUBLE_EQ(m.crownRadius_m, 3.0);  // the side branch's end
  EXPECT_NEAR(m.trunkDiameter_m, 0.4, 1e-6);
}

TEST(Skeleton, SegmentEndFollowsItsAxis) {
  BranchSegment s;
  s.start = glm::vec3(1, 2, 3);
  s.length_m = 2.0f;
  EXPECT_EQ(s.end(), glm::vec3(1, 4, 3));
}

}  // namespace eco
