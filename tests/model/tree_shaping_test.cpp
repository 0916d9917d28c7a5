#include "model/tree_shaping.hpp"

#include <cstring>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/angles.hpp"
#include "model/tree_generator.hpp"
#include "test_support.hpp"

namespace eco {
namespace {

TreeBuildOptions shaped(const SiteShaping& site) {
  TreeBuildOptions options;
  options.seed = 7;
  options.lean = shapingLean(site);
  options.clearBole = site.clearBole;
  return options;
}

// The leaves' centre, horizontally (east, south), relative to the tree's height.
glm::dvec2 crownOffset(const TreeSkeleton& tree) {
  glm::dvec3 sum(0.0);
  for (const Leaf& leaf : tree.leaves) sum += glm::dvec3(leaf.position);
  const glm::dvec3 centre = sum / static_cast<double>(tree.leaves.size());
  return glm::dvec2(centre.x, centre.z) / measure(tree).height_m;
}

bool sameBytes(const TreeSkeleton& a, const TreeSkeleton& b) {
  // Frames and positions compared exactly; BranchSegment has padding, so field by field.
  if (a.segments.size() != b.segments.size() || a.leaves.size() != b.leaves.size()) return false;
  for (std::size_t i = 0; i < a.segments.size(); ++i) {
    const BranchSegment &x = a.segments[i], &y = b.segments[i];
    if (std::memcmp(&x.start, &y.start, sizeof x.start) != 0 ||
        std::memcmp(&x.frame, &y.frame, sizeof x.frame) != 0 || x.length_m != y.length_m ||
        x.parent != y.parent || x.startRadius_m != y.startRadius_m)
      return false;
  }
  for (std::size_t i = 0; i < a.leaves.size(); ++i)
    if (std::memcmp(&a.leaves[i].position, &b.leaves[i].position, sizeof(glm::vec3)) != 0 ||
        std::memcmp(&a.leaves[i].normal, &b.leaves[i].normal, sizeof(glm::vec3)) != 0)
      return false;
  return true;
}

TEST(TreeShaping, ANeutralSiteLeavesThePapersTreesUnchanged) {
  for (const char* name : {"beech", "pine"}) {
    const Species species = test::loadNamed(name);
    const SiteShaping neutral;
    EXPECT_TRUE(neutral.neutral());
    EXPECT_EQ(shapingLean(neutral), glm::dvec2(0.0));
    TreeBuildOptions plain;
    plain.seed = 7;
    EXPECT_TRUE(sameBytes(buildTree(species, plain), buildTree(species, shaped(neutral)))) << name;
  }
}

TEST(TreeShaping, TheLeanAddsTheStatedHorizontalVector) {
  SiteShaping site;
  site.light = {1.0, 0.0};  // from the east only
  EXPECT_EQ(shapingLean(site), glm::dvec2(kPhototropism_wg, 0.0));
  site.light = {0.0, 0.5};  // half one-sided, from the south
  EXPECT_EQ(shapingLean(site), glm::dvec2(0.0, 0.5 * kPhototropism_wg));
  site.wind = {-1.0, 0.0};  // blowing west, fully exposed
  EXPECT_EQ(shapingLean(site), glm::dvec2(-kWindLean_wg, 0.5 * kPhototropism_wg));
  site = SiteShaping{};
  site.light = {0.8, 0.8};  // a file's rounding past 1 counts as 1
  EXPECT_NEAR(glm::length(shapingLean(site)), kPhototropism_wg, 1e-12);
}

// The crown's centre moves toward the light, the further the more one-sided it is; at a
// forest edge (light from one half of the sky, 0.65) by at least the stated share of the
// height: the paper's pine, whose stem carries its strands high, by 8 %, its beech, whose
// strands part low, by 1.5 %.
TEST(TreeShaping, OneSidedLightMovesTheCrownTowardIt) {
  for (auto [name, atEdge] : {std::pair{"pine", 0.08}, std::pair{"beech", 0.015}}) {
    const Species species = test::loadNamed(name);
    TreeBuildOptions plain;
    plain.seed = 7;
    const glm::dvec2 upright = crownOffset(buildTree(species, plain));
    double previous = 0.0;
    for (double sidedness : {0.3, 0.65, 1.0}) {
      SiteShaping site;
      site.light = {sidedness, 0.0};  // light from the east
      const glm::dvec2 offset = crownOffset(buildTree(species, shaped(site))) - upright;
      EXPECT_GT(offset.x, previous) << name << " " << sidedness;  // more one-sided, further east
      EXPECT_NEAR(offset.y, 0.0, 0.3 * offset.x) << name << " " << sidedness;
      if (sidedness == 0.65) {
        EXPECT_GT(offset.x, atEdge) << name;
      }
      previous = offset.x;
    }
  }
}

TEST(TreeShaping, ExposureLeansPineDownwind) {
  const Species pine = test::loadNamed("pine");
  TreeBuildOptions plain;
  plain.seed = 7;
  const glm::dvec2 upright = crownOffset(buildTree(pine, plain));
  SiteShaping ridge;
  ridge.wind = {0.0, 1.0};  // the wind blows south, the most exposed site
  const glm::dvec2 offset = crownOffset(buildTree(pine, shaped(ridge))) - upright;
  EXPECT_GT(offset.y, 0.12);
  EXPECT_NEAR(offset.x, 0.0, 0.3 * offset.y);
}

TEST(TreeShaping, PruningClearsTheBoleBelowTheCrownBase) {
  const Species beech = test::loadNamed("beech");
  TreeBuildOptions plain;
  plain.seed = 7;
  const TreeSkeleton open = buildTree(beech, plain);
  for (double share : {0.3, 0.5}) {
    SiteShaping crowded;
    crowded.clearBole = share;
    const TreeSkeleton pruned = buildTree(beech, shaped(crowded));
    ASSERT_LT(pruned.segments.size(), open.segments.size()) << share;
    // The stem stays whole: the base and every segment continuing it are kept, so the tree
    // is as tall as before.
    EXPECT_NEAR(measure(pruned).height_m, measure(open).height_m, 1e-6) << share;
    // Nothing but the stem below the clear height (the stem of the paper's beech stands
    // within a few degrees of vertical, so its length is its height).
    const double clear = share * measure(open).height_m;
    double lowestLeaf = 1e9, lowestLeafOpen = 1e9;
    for (const Leaf& leaf : pruned.leaves)
      lowestLeaf = std::min<double>(lowestLeaf, leaf.position.y);
    for (const Leaf& leaf : open.leaves)
      lowestLeafOpen = std::min<double>(lowestLeafOpen, leaf.position.y);
    EXPECT_GT(lowestLeaf, lowestLeafOpen) << share;
    EXPECT_GT(lowestLeaf, 0.8 * clear) << share;
    for (std::size_t i = 0; i < pruned.segments.size(); ++i) {
      EXPECT_LT(pruned.segments[i].parent, static_cast<std::int32_t>(i));  // parents first
    }
  }
}

TEST(TreeShaping, EveryWindPoseLosesTheSameBranches) {
  const Species beech = test::loadNamed("beech");
  SiteShaping crowded;
  crowded.clearBole = 0.4;
  TreeBuildOptions rest = shaped(crowded);
  TreeBuildOptions windy = rest;
  windy.windDirected = 4.0;
  windy.windDirection = glm::dvec3(1.0, 0.2, 0.0);
  windy.windUndirected = 3.0;
  windy.windTime = 1.0;
  const TreeSkeleton a = buildTree(beech, rest), b = buildTree(beech, windy);
  ASSERT_EQ(a.segments.size(), b.segments.size());
  ASSERT_EQ(a.leaves.size(), b.leaves.size());
  for (std::size_t i = 0; i < a.segments.size(); ++i)
    EXPECT_EQ(a.segments[i].parent, b.segments[i].parent);
}

}  // namespace
}  // namespace eco
