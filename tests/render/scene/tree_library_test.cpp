#include "render/scene/tree_library.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "render_support.hpp"

namespace eco {
namespace {

TEST(TreeLibrary, HoldsEverySpeciesVariantAndAgeClassInOrder) {
  const TreeLibrary& library = test::smallLibrary();
  ASSERT_EQ(library.types().size(), 2u * 1u * 2u);
  for (int s = 0; s < 2; ++s)
    for (int a = 0; a < 2; ++a) {
      const TreeType& t = library.types()[library.typeIndex(s, 0, a)];
      EXPECT_EQ(t.species, s);
      EXPECT_EQ(t.ageClass, a);
      EXPECT_GT(t.meshes.lods[0].triangleCount(), t.meshes.lods[1].triangleCount());
      EXPECT_GT(t.meshes.lods[1].triangleCount(), t.meshes.lods[2].triangleCount());
    }
  // Older classes are taller.
  EXPECT_LT(library.types()[library.typeIndex(0, 0, 0)].height_m,
            library.types()[library.typeIndex(0, 0, 1)].height_m);
}

TEST(TreeLibrary, BoundsHoldEveryVertexOfEveryLevel) {
  for (const TreeType& t : test::smallLibrary().types())
    for (const WindMesh& lod : t.meshes.lods)
      for (const WindPart& part : lod.parts)
        for (const TreeVertex& v : part.vertices)
          ASSERT_LE(glm::distance(v.position, glm::vec3(t.bounds)), t.bounds.w * 1.0001f);
}

TEST(TreeLibrary, PlantsTakeTheAgeClassNearestInRelativeHeight) {
  const TreeLibrary& library = test::smallLibrary();
  const float young = library.types()[library.typeIndex(0, 0, 0)].height_m;
  const float mature = library.types()[library.typeIndex(0, 0, 1)].height_m;
  const float maxHeight = 40.0f;
  // A plant at the young class's share of the species' height is drawn as the young tree.
  EXPECT_EQ(library.typeFor(0, 7, maxHeight * young / mature, maxHeight),
            library.typeIndex(0, 0, 0));
  EXPECT_EQ(library.typeFor(0, 7, 0.9f * maxHeight, maxHeight), library.typeIndex(0, 0, 1));
  EXPECT_EQ(library.typeFor(1, 7, 0.1f, maxHeight), library.typeIndex(1, 0, 0));
}

TEST(TreeLibrary, BlendsMoveSmoothlyFromOneAgeClassToTheNext) {
  const TreeLibrary& library = test::smallLibrary();
  const float young = library.types()[library.typeIndex(0, 0, 0)].height_m;
  const float mature = library.types()[library.typeIndex(0, 0, 1)].height_m;
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
  for (std::size_t t = 0; t < library.types().size(); ++t) {
    const TreeType& type = library.types()[t];
    EXPECT_EQ(type.impostorSource, library.typeIndex(type.species, 0, type.ageClass));
  }
}

TEST(TreeLibrary, AShapedLibraryHasATypePerCrownClassWithItsClearBole) {
  const TreeLibrary& shaped = test::shapedLibrary();
  ASSERT_EQ(shaped.types().size(), kShapedClearBoleClasses.size());
  float previousLowestLeaf = -1.0f;
  for (int c = 0; c < static_cast<int>(kShapedClearBoleClasses.size()); ++c) {
    const TreeType& type = shaped.types()[shaped.typeIndex(0, 0, 0, c)];
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
  std::vector<TreeType> types = {grid.types()[grid.typeIndex(0, 0, 1)],
                                 grid.types()[grid.typeIndex(1, 0, 0)]};
  TreeLibrary library(grid.species(), types);
  ASSERT_EQ(library.types().size(), 2u);
  EXPECT_EQ(library.types()[1].impostorSource, 1);
  EXPECT_EQ(library.maxHeight_m(0), types[0].height_m);  // the tallest of its types
  library.setType(0, grid.types()[grid.typeIndex(0, 0, 0)]);
  EXPECT_EQ(library.types()[0].height_m, grid.types()[grid.typeIndex(0, 0, 0)].height_m);
  EXPECT_EQ(library.types()[0].impostorSource, 0);
}

}  // namespace
}  // namespace eco
