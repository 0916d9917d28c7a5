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
    std::size_t t0 = buildLod(tree, species, 0).triangleCount();
    std::size_t t1 = buildLod(tree, species, 1).triangleCount();
    std::size_t t2 = buildLod(tree, species, 2).triangleCount();
    EXPECT_LT(t1, t0 / 3) << name;
    EXPECT_LT(t2, t1) << name;
    EXPECT_GE(t2, 100u) << name;
    EXPECT_LE(t2, 400u) << name << ": a few hundred triangles";
  }
}

TEST(Lod, Lod1KeepsTheVisibleLeafArea) {
  for (const char* name : {"beech", "pine"}) {
    Species species = test::loadNamed(name);
    TreeSkeleton tree = buildStrandTree(species, {});
    double visible = 0.0;
    for (const Leaf& leaf : tree.leaves) visible += visibleLeafArea(species, leaf.size_m);
    TreeMesh lod1 = buildLod(tree, species, 1);
    const MeshPart* clusters = lod1.find(MaterialKind::LeafCluster);
    ASSERT_NE(clusters, nullptr);
    EXPECT_EQ(lod1.find(MaterialKind::Leaf), nullptr);
    double cardArea = 0.0;
    for (std::size_t t = 0; t < clusters->indices.size(); t += 3) {
      glm::vec3 a = clusters->positions[clusters->indices[t]],
                b = clusters->positions[clusters->indices[t + 1]];
      glm::vec3 c = clusters->positions[clusters->indices[t + 2]];
      cardArea += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    double coverage = clustersOfNeedles(species) ? kNeedleClusterCoverage : kLeafClusterCoverage;
    EXPECT_NEAR(cardArea * coverage, visible, 0.02 * visible) << name;
    // At LOD0 each leaf is a card of two triangles; the clusters take at most half as many.
    EXPECT_LT(clusters->triangleCount(), tree.leaves.size()) << name;
  }
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
