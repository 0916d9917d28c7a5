#include "model/mesh/tree_mesher.hpp"

#include <map>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "model/strand_model.hpp"
#include "test_support.hpp"

namespace eco {
namespace {

// Edges used by exactly one triangle, after welding vertices at the same position (the
// texture seam duplicates the first vertex of every ring).
std::vector<std::pair<glm::vec3, glm::vec3>> openEdges(const MeshPart& part) {
  auto keyOf = [](glm::vec3 p) {
    return std::tuple{std::lround(p.x * 1e5), std::lround(p.y * 1e5), std::lround(p.z * 1e5)};
  };
  std::map<decltype(keyOf(glm::vec3())), std::uint32_t> weld;
  std::vector<std::uint32_t> welded(part.positions.size());
  for (std::size_t i = 0; i < part.positions.size(); ++i)
    welded[i] =
        weld.try_emplace(keyOf(part.positions[i]), static_cast<std::uint32_t>(i)).first->second;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; t < part.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      std::uint32_t a = welded[part.indices[t + e]], b = welded[part.indices[t + (e + 1) % 3]];
      if (a == b) continue;
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::pair<glm::vec3, glm::vec3>> open;
  for (auto [edge, count] : uses)
    if (count == 1) open.push_back({part.positions[edge.first], part.positions[edge.second]});
  return open;
}

}  // namespace

TEST(TreeMesher, JointsLeaveNoGaps) {
  // Every chain is a closed tube; the only open edges are the first rings of minor
  // branches, which must lie inside their parent's wood at the joint.
  TreeSkeleton tree = buildStrandTree(test::loadNamed("beech"), {});
  MeshPart bark{MaterialKind::Bark, {}, {}, {}, {}};
  meshBranches(tree, MeshOptions{}, bark);
  std::vector<const BranchSegment*> minorBases;
  for (const BranchSegment& s : tree.segments)
    if (!s.continuesParent && s.parent >= 0) minorBases.push_back(&s);
  auto open = openEdges(bark);
  EXPECT_GT(open.size(), 0u);
  const float tolerance = 1e-4f;  // metres
  for (auto [a, b] : open) {
    bool insideAParent = false;
    for (const BranchSegment* s : minorBases) {
      const BranchSegment& parent = tree.segments[s->parent];
      if (glm::length(a - s->start) <= parent.endRadius_m + tolerance &&
          glm::length(b - s->start) <= parent.endRadius_m + tolerance) {
        insideAParent = true;
        break;
      }
    }
    ASSERT_TRUE(insideAParent) << "open edge at " << a.x << "," << a.y << "," << a.z;
  }
}

TEST(TreeMesher, MajorContinuationSharesOneRing) {
  // A straight two-segment chain: the joint ring is shared, so the tube has rings for
  // 3 positions, a base cap and a tip cone, and no open edge at all.
  TreeSkeleton tree;
  BranchSegment trunk;
  trunk.length_m = 2.0f;
  trunk.startRadius_m = 0.2f;
  trunk.endRadius_m = 0.15f;
  trunk.strands = 2;
  tree.segments.push_back(trunk);
  BranchSegment top = trunk;
  top.start = trunk.end();
  top.parent = 0;
  top.continuesParent = true;
  top.startRadius_m = 0.15f;
  top.endRadius_m = 0.05f;
  top.strands = 1;
  tree.segments.push_back(top);
  MeshPart bark{MaterialKind::Bark, {}, {}, {}, {}};
  MeshOptions options;
  options.maxSides = 6;
  meshBranches(tree, options, bark);
  EXPECT_EQ(bark.positions.size(), 3u * 7u + 2u);
  EXPECT_EQ(bark.triangleCount(), 2u * 6u * 2u + 6u + 6u);
  EXPECT_TRUE(openEdges(bark).empty());
  for (std::size_t i = 0; i < bark.normals.size(); ++i)
    EXPECT_NEAR(glm::length(bark.normals[i]), 1.0f, 1e-5f);
}

TEST(TreeMesher, TrianglesFaceOutward) {
  TreeSkeleton tree = buildStrandTree(test::loadNamed("maple"), {.leaves = false});
  MeshPart bark{MaterialKind::Bark, {}, {}, {}, {}};
  meshBranches(tree, MeshOptions{}, bark);
  std::size_t outward = 0, total = 0;
  for (std::size_t t = 0; t < bark.indices.size(); t += 3) {
    glm::vec3 a = bark.positions[bark.indices[t]], b = bark.positions[bark.indices[t + 1]];
    glm::vec3 c = bark.positions[bark.indices[t + 2]];
    glm::vec3 faceNormal = glm::cross(b - a, c - a);
    if (glm::length(faceNormal) < 1e-12f) continue;
    glm::vec3 vertexNormals = bark.normals[bark.indices[t]] + bark.normals[bark.indices[t + 1]] +
                              bark.normals[bark.indices[t + 2]];
    outward += glm::dot(faceNormal, vertexNormals) > 0.0f ? 1 : 0;
    ++total;
  }
  EXPECT_GT(static_cast<double>(outward) / total, 0.99);
}

TEST(TreeMesher, SidesFollowOptionsAndLeavesBecomeCards) {
  Species beech = test::loadNamed("beech");
  TreeSkeleton tree = buildStrandTree(beech, {});
  MeshOptions options;
  options.maxSides = 12;
  options.minSides = 5;
  TreeMesh fine = meshTree(tree, options);
  options.maxSides = 4;
  options.minSides = 3;
  TreeMesh coarse = meshTree(tree, options);
  EXPECT_GT(fine.find(MaterialKind::Bark)->triangleCount(),
            1.5 * coarse.find(MaterialKind::Bark)->triangleCount());
  ASSERT_NE(fine.find(MaterialKind::Leaf), nullptr);
  EXPECT_EQ(fine.find(MaterialKind::Leaf)->triangleCount(), 2 * tree.leaves.size());
  EXPECT_EQ(fine.find(MaterialKind::Needle), nullptr);
}

TEST(TreeMesher, ConiferousLeavesAreCrossedNeedles) {
  Species pine = test::loadNamed("pine");
  pine.strand.leafDistribution = LeafDistribution::Coniferous;
  pine.strand.strands = 200;
  TreeSkeleton tree = buildStrandTree(pine, {});
  TreeMesh mesh = meshTree(tree, MeshOptions{});
  ASSERT_NE(mesh.find(MaterialKind::Needle), nullptr);
  EXPECT_EQ(mesh.find(MaterialKind::Needle)->triangleCount(), 4 * tree.leaves.size());
}

}  // namespace eco
