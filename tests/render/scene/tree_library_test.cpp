#include "render/scene/tree_library.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "render_support.hpp"

namespace eco {
namespace {

TEST(TreeLibrary, HoldsEverySpeciesVariantAndAgeClassInOrder) {
  const TreeLibrary& library = test::smallLibrary();
  ASSERT_EQ(library.typeCount(), 2 * 1 * 2);
  for (int s = 0; s < 2; ++s)
    for (int a = 0; a < 2; ++a) {
      const TreeType& t = library.type(library.typeIndex(s, 0, a));
      EXPECT_EQ(t.species, s);
      EXPECT_EQ(t.ageClass, a);
      EXPECT_GT(t.meshes.lods[0].triangleCount(), t.meshes.lods[1].triangleCount());
      EXPECT_GT(t.meshes.lods[1].triangleCount(), t.meshes.lods[2].triangleCount());
    }
  // Older classes are taller.
  EXPECT_LT(library.type(library.typeIndex(0, 0, 0)).height_m,
            library.type(library.typeIndex(0, 0, 1)).height_m);
}

// A type is built on first use, alone or beside others, in any order: the same type.
TEST(TreeLibrary, TypesBuiltOnFirstUseAreTheSameInAnyOrderAndBesideOthers) {
  const LibrarySettings settings{.variants = 2, .ageClasses = {0.4, 1.0}};
  const TreeLibrary one({test::namedLibrarySpecies("shrub")}, settings);
  const TreeLibrary all({test::namedLibrarySpecies("shrub")}, settings);
  ASSERT_EQ(one.builtTypeCount(), 0) << "sizes only, until a type is used";
  std::vector<float> heights;
  std::vector<int> every(one.typeCount());
  for (int t = 0; t < one.typeCount(); ++t) heights.push_back(one.typeHeight_m(t)), every[t] = t;
  for (int t = one.typeCount() - 1; t >= 0; --t) one.type(t);  // one by one, backwards
  all.build(every);                                            // side by side
  ASSERT_EQ(one.builtTypeCount(), one.typeCount());
  ASSERT_EQ(all.builtTypeCount(), all.typeCount());
  for (int t = 0; t < one.typeCount(); ++t) {
    SCOPED_TRACE(t);
    const TreeType &a = one.type(t), &b = all.type(t);
    EXPECT_EQ(a.height_m, heights[t]) << "the size known before the build";
    EXPECT_EQ(a.bounds, b.bounds);
    EXPECT_EQ(a.envelope_m, b.envelope_m);
    for (int lod = 0; lod < kLodCount; ++lod) {
      ASSERT_GT(a.meshes.lods[lod].triangleCount(), 0u);
      ASSERT_EQ(a.meshes.lods[lod].parts.size(), b.meshes.lods[lod].parts.size());
      for (std::size_t p = 0; p < a.meshes.lods[lod].parts.size(); ++p) {
        const WindPart &pa = a.meshes.lods[lod].parts[p], &pb = b.meshes.lods[lod].parts[p];
        EXPECT_EQ(pa.indices, pb.indices);
        ASSERT_EQ(pa.vertices.size(), pb.vertices.size());
        for (std::size_t v = 0; v < pa.vertices.size(); ++v)
          ASSERT_EQ(pa.vertices[v].position, pb.vertices[v].position);
      }
    }
  }
}

TEST(TreeLibrary, BoundsHoldEveryVertexOfEveryLevel) {
  const TreeLibrary& library = test::smallLibrary();
  for (int type = 0; type < library.typeCount(); ++type)
    for (const TreeType& t = library.type(type); const WindMesh& lod : t.meshes.lods)
      for (const WindPart& part : lod.parts)
        for (const TreeVertex& v : part.vertices)
          ASSERT_LE(glm::distance(v.position, glm::vec3(t.bounds)), t.bounds.w * 1.0001f);
}

TEST(TreeLibrary, PlantsTakeTheAgeClassNearestInRelativeHeight) {
  const TreeLibrary& library = test::smallLibrary();
  const float young = library.type(library.typeIndex(0, 0, 0)).height_m;
  const float mature = library.type(library.typeIndex(0, 0, 1)).height_m;
  const float maxHeight = 40.0f;
  // A plant at the young class's share of the species' height is drawn as the young tree.
  EXPECT_EQ(library.typeFor(0, 7, maxHeight * young / mature, maxHeight),
            library.typeIndex(0, 0, 0));
  EXPECT_EQ(library.typeFor(0, 7, 0.9f * maxHeight, maxHeight), library.typeIndex(0, 0, 1));
  EXPECT_EQ(library.typeFor(1, 7, 0.1f, maxHeight), library.typeIndex(1, 0, 0));
}

TEST(TreeLibrary, BlendsMoveSmoothlyFromOneAgeClassToTheNext) {
  const TreeLibrary& library = test::smallLibrary();
  const float young = library.type(library.typeIndex(0, 0, 0)).height_m;
  const float mature = library.type(library.typeIndex(0, 0, 1)).height_m;
  const float maxHeight = 40.0f;
  const float youngHeight = maxHeight * young / mature;
  EXPECT_EQ(library.blendFor(0, 7, 0.5f * youngHeight, maxHeight).blendType, -1);
  EXPECT_EQ(library.blendFor(0, 7, 1.1f * maxHeight, maxHeight).type, library.typeIndex(0, 0, 1));
  float previous = -1.0f;
  for (float h = youngHeight * 1.01f; h < maxHeight * 0.99f; h *= 1.05f) {
    const TreeLibrary::Blend b = library.blendFor(0, 7, h, maxHeight);
    EXPECT_EQ(b.type, library.typeIndex(0, 0, 0));
    EXPECT_EQ(b.blendType, library.typeIndex(0, 0, 1));
    EXPECT_GT(b.blendWeight, previous);
    previous = b.blendWeight;
  }
  EXPECT_GT(previous, 0.9f);  // the last step stops 5 % short of the mature class
}

TEST(TreeLibrary, GridTypesShareTheirAgeClassesImpostor) {
  const TreeLibrary& library = test::smallLibrary();
  for (int t = 0; t < library.typeCount(); ++t) {
    const TreeType& type = library.type(t);
    EXPECT_EQ(type.impostorSource, library.typeIndex(type.species, 0, type.ageClass));
  }
}

TEST(TreeLibrary, AShapedLibraryHasATypePerCrownClassWithItsClearBole) {
  const TreeLibrary& shaped = test::shapedLibrary();
  ASSERT_EQ(shaped.typeCount(), static_cast<int>(kShapedClearBoleClasses.size()));
  float previousLowestLeaf = -1.0f;
  for (int c = 0; c < static_cast<int>(kShapedClearBoleClasses.size()); ++c) {
    const TreeType& type = shaped.type(shaped.typeIndex(0, 0, 0, c));
    EXPECT_EQ(type.crownClass, c);
    EXPECT_EQ(type.clearBole, kShapedClearBoleClasses[c]);
    // A longer clear bole: the crown starts higher.
    float lowestLeaf = 1e30f;
    for (const WindPart& part : type.meshes.lods[0].parts)
      if (part.material != MaterialKind::Bark)
        for (const TreeVertex& v : part.vertices) lowestLeaf = std::min(lowestLeaf, v.position.y);
    EXPECT_GT(lowestLeaf, previousLowestLeaf) << c;
    previousLowestLeaf = lowestLeaf;
    // A strong lean moves the crown less than the bend bases' straight line (wind_mesh.hpp).
    EXPECT_GT(type.leanResponse.bend[0], 0.0f);
    EXPECT_LT(type.leanResponse.bend[1], static_cast<float>(kLeanSamples_wg[1]));
  }
  EXPECT_EQ(shaped.crownClassFor(0.0), 0);
  EXPECT_EQ(shaped.crownClassFor(0.4), 1);
  EXPECT_EQ(shaped.crownClassFor(0.9), 2);
  EXPECT_EQ(test::smallLibrary().crownClassFor(0.9), 0);  // without shaping: one class
}

TEST(TreeLibrary, GivenTypesAreEachTheirOwnAndCanBeReplaced) {
  const TreeLibrary& grid = test::smallLibrary();
  std::vector<TreeType> types = {grid.type(grid.typeIndex(0, 0, 1)),
                                 grid.type(grid.typeIndex(1, 0, 0))};
  TreeLibrary library(grid.species(), types);
  ASSERT_EQ(library.typeCount(), 2);
  EXPECT_EQ(library.type(1).impostorSource, 1);
  EXPECT_EQ(library.maxHeight_m(0), types[0].height_m);  // the tallest of its types
  library.setType(0, grid.type(grid.typeIndex(0, 0, 0)));
  EXPECT_EQ(library.type(0).height_m, grid.type(grid.typeIndex(0, 0, 0)).height_m);
  EXPECT_EQ(library.type(0).impostorSource, 0);
}

}  // namespace
}  // namespace eco
