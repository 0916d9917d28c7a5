#include "render/scene/crown_shade.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include "model/mesh/lod.hpp"
#include "render/scene/tree_library.hpp"
#include "render/scene/wind_mesh.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

constexpr float kRadius_m = 2.0f;
constexpr float kSpacing_m = 0.2f;
constexpr float kLeafSize_m = 0.1f;

// Leaves on a lattice filling a ball: a uniform leaf area density, known exactly.
TreeSkeleton ballOfLeaves(glm::vec3 centre) {
  TreeSkeleton tree;
  const int n = static_cast<int>(kRadius_m / kSpacing_m);
  for (int x = -n; x <= n; ++x)
    for (int y = -n; y <= n; ++y)
      for (int z = -n; z <= n; ++z) {
        const glm::vec3 offset = glm::vec3(x, y, z) * kSpacing_m;
        if (glm::length(offset) > kRadius_m) continue;
        Leaf leaf;
        // The blade's middle on the lattice point: the shade bins leaves there.
        leaf.direction = glm::vec3(1.0f, 0.0f, 0.0f);
        leaf.position = centre + offset - 0.5f * kLeafSize_m * leaf.direction;
        leaf.size_m = kLeafSize_m;
        tree.leaves.push_back(leaf);
      }
  return tree;
}

TEST(CrownShade, WithoutLeavesTheWholeSkyIsSeen) {
  const Species beech = test::loadNamedSpecies("beech");
  const CrownShade shade(TreeSkeleton{}, beech);
  EXPECT_FLOAT_EQ(shade.skyVisibility({0.0f, 5.0f, 0.0f}), 1.0f);
}

// At the centre of a ball of uniform leaf area density a, every way out to the sky crosses
// R of foliage: the visibility is Beer-Lambert's exp(-G a R) whatever the direction.
TEST(CrownShade, TheCentreOfAUniformBallSeesExpOfMinusGTimesDensityTimesRadius) {
  const Species beech = test::loadNamedSpecies("beech");
  const glm::vec3 centre(0.0f, 6.0f, 0.0f);
  const CrownShade shade(ballOfLeaves(centre), beech);
  const float density =
      visibleLeafArea(beech, kLeafSize_m) / (kSpacing_m * kSpacing_m * kSpacing_m);
  const float expected = std::exp(-CrownShade::kLeafProjection * density * kRadius_m);
  ASSERT_GT(expected, 0.2f);  // a crown thin enough for the grid to resolve
  ASSERT_LT(expected, 0.9f);
  EXPECT_NEAR(shade.skyVisibility(centre), expected, 0.15f * expected);
}

TEST(CrownShade, InnerAndLowerLeavesSeeLessSkyThanTheTop) {
  const Species beech = test::loadNamedSpecies("beech");
  const glm::vec3 centre(0.0f, 6.0f, 0.0f);
  const CrownShade shade(ballOfLeaves(centre), beech);
  const float top = shade.skyVisibility(centre + glm::vec3(0.0f, 0.95f * kRadius_m, 0.0f));
  const float middle = shade.skyVisibility(centre);
  const float bottom = shade.skyVisibility(centre - glm::vec3(0.0f, 0.95f * kRadius_m, 0.0f));
  const float side = shade.skyVisibility(centre + glm::vec3(0.95f * kRadius_m, 0.0f, 0.0f));
  EXPECT_GT(top, 0.85f);
  EXPECT_GT(top, side);
  EXPECT_GT(side, middle);
  EXPECT_GT(middle, bottom);
  // The stem below the crown sees the sky through all of it.
  EXPECT_NEAR(shade.skyVisibility(centre - glm::vec3(0.0f, 4.0f, 0.0f)), bottom, 0.05f);
}

// Built on many threads at once (the library's types are), a crown is shaded alike: the
// march never reads outside its grid, even where a step ends a rounding error short of it.
TEST(CrownShade, IsTheSameWhateverThreadComputesIt) {
  const Species beech = test::loadNamedSpecies("beech");
  TreeSkeleton tree;
  buildWindLods(beech, 1, 1.0, &tree);
  const CrownShade reference(tree, beech);
  std::vector<int> differing(16, 0);
  tbb::parallel_for(0, 16, [&](int k) {
    const CrownShade shade(tree, beech);
    for (const Leaf& leaf : tree.leaves)
      differing[k] += shade.skyVisibility(leaf.position) != reference.skyVisibility(leaf.position);
  });
  for (int k = 0; k < 16; ++k) EXPECT_EQ(differing[k], 0) << "copy " << k;
}

// The library shades every level of a tree from its LOD0 leaves: a mature tree's inner
// leaves are darker than its outer ones at every level, and all levels agree.
TEST(CrownShade, TheLibraryShadesEveryLevelOfATreeAlike) {
  const TreeLibrary& library = test::smallLibrary();
  const TreeType& mature = library.type(library.typeIndex(0, 0, 1));
  for (int lod = 0; lod < kLodCount; ++lod) {
    float lo = 1.0f, hi = 0.0f;
    for (const WindPart& part : mature.meshes.lods[lod].parts)
      for (const TreeVertex& v : part.vertices) {
        EXPECT_GE(v.skyVisibility, 0.0f);
        EXPECT_LE(v.skyVisibility, 1.0f);
        lo = std::min(lo, v.skyVisibility);
        hi = std::max(hi, v.skyVisibility);
      }
    EXPECT_LT(lo, 0.8f * hi) << "LOD" << lod << " is evenly lit";
  }
}

}  // namespace
}  // namespace eco
