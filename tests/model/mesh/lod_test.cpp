#include "model/mesh/lod.hpp"

#include <gtest/gtest.h>
#include <glm/common.hpp>

#include "model/export/tree_export.hpp"
#include "model/mesh/textures.hpp"
#include "model/mesh/tree_mesher.hpp"
#include "model/strand_model.hpp"
#include "test_support.hpp"

namespace eco {

TEST(Lod, EachLevelIsCheaper) {
  for (const char* name : {"beech", "pine", "maple", "shrub"}) {
    Species species = test::loadNamed(name);
    TreeSkeleton tree = buildStrandTree(species, {});
    TreeMesh lod0 = buildLod(tree, species, 0), lod1 = buildLod(tree, species, 1);
    std::size_t t0 = lod0.triangleCount(), t1 = lod1.triangleCount();
    std::size_t t2 = buildLod(tree, species, 2).triangleCount();
    // LOD1's branches take at most a third of LOD0's triangles; with the needles gathered
    // into clusters the whole tree does too (broadleaves keep their leaves).
    EXPECT_LT(lod1.find(MaterialKind::Bark)->triangleCount(),
              lod0.find(MaterialKind::Bark)->triangleCount() / 3)
        << name;
    if (bearsNeedles(species)) {
      EXPECT_LT(t1, t0 / 3) << name;
    }
    EXPECT_LT(t1, t0) << name;
    EXPECT_LT(t2, t1) << name;
    EXPECT_GE(t2, 100u) << name;
    EXPECT_LE(t2, 400u) << name << ": a few hundred triangles";
  }
}

TEST(Lod, Lod1KeepsABroadleafsOwnLeaves) {
  for (const char* name : {"beech", "maple"}) {
    Species species = test::loadNamed(name);
    ASSERT_FALSE(bearsNeedles(species)) << name;
    TreeSkeleton tree = buildStrandTree(species, {});
    TreeMesh lod0 = buildLod(tree, species, 0), lod1 = buildLod(tree, species, 1);
    const MeshPart* leaves0 = lod0.find(MaterialKind::Leaf);
    const MeshPart* leaves1 = lod1.find(MaterialKind::Leaf);
    ASSERT_NE(leaves0, nullptr);
    ASSERT_NE(leaves1, nullptr);
    EXPECT_EQ(lod1.find(MaterialKind::LeafCluster), nullptr) << name;
    EXPECT_EQ(leaves1->indices, leaves0->indices) << name;
    EXPECT_EQ(leaves1->positions, leaves0->positions) << name;
    EXPECT_EQ(leaves1->uvs, leaves0->uvs) << name;
  }
}

TEST(Lod, Lod1GathersNeedlesKeepingTheirVisibleArea) {
  Species species = test::loadNamed("pine");
  ASSERT_TRUE(bearsNeedles(species));
  TreeSkeleton tree = buildStrandTree(species, {});
  double visible = 0.0;
  for (const Leaf& leaf : tree.leaves) visible += visibleLeafArea(species, leaf.size_m);
  TreeMesh lod1 = buildLod(tree, species, 1);
  const MeshPart* clusters = lod1.find(MaterialKind::LeafCluster);
  ASSERT_NE(clusters, nullptr);
  EXPECT_EQ(lod1.find(MaterialKind::Leaf), nullptr);
  EXPECT_EQ(lod1.find(MaterialKind::Needle), nullptr);
  double cardArea = 0.0;
  for (std::size_t t = 0; t < clusters->indices.size(); t += 3) {
    glm::vec3 a = clusters->positions[clusters->indices[t]],
              b = clusters->positions[clusters->indices[t + 1]];
    glm::vec3 c = clusters->positions[clusters->indices[t + 2]];
    cardArea += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  EXPECT_NEAR(cardArea * kNeedleClusterCoverage, visible, 0.02 * visible);
  // At LOD0 each tuft is a card of two triangles; the clusters take at most half as many.
  EXPECT_LT(clusters->triangleCount(), tree.leaves.size());
}

TEST(Lod, VisibleLeafAreaFollowsTheTexture) {
  Species beech = test::loadNamed("beech");
  EXPECT_NEAR(visibleLeafArea(beech, 0.2f), 0.04 * 0.6 * kBroadleafCoverage, 1e-6);
  Species pine = test::loadNamed("pine");
  EXPECT_NEAR(visibleLeafArea(pine, 0.2f), 0.04 * 0.9 * kNeedleTuftCoverage, 1e-6);
  pine.strand.leafDistribution = LeafDistribution::Coniferous;
  EXPECT_NEAR(visibleLeafArea(pine, 0.2f), 2 * 0.04 * kNeedleAspect * kNeedleCoverage, 1e-6);
}

TEST(Lod, Lod2KeepsTheSilhouette) {
  for (const char* name : {"beech", "maple"}) {
    Species species = test::loadNamed(name);
    TreeSkeleton tree = buildStrandTree(species, {});
    Bounds full = boundsOf(buildLod(tree, species, 0));
    Bounds proxy = boundsOf(buildLod(tree, species, 2));
    glm::vec3 fullSize = full.max - full.min, proxySize = proxy.max - proxy.min;
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_GT(proxySize[axis], 0.8f * fullSize[axis]) << name << " axis " << axis;
      EXPECT_LT(proxySize[axis], 1.15f * fullSize[axis]) << name << " axis " << axis;
    }
    EXPECT_NEAR(proxy.min.y, 0.0f, 1e-4f) << "the stem proxy reaches the ground";
  }
}

}  // namespace eco
