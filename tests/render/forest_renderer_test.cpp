#include "render/forest_renderer.hpp"

#include <gtest/gtest.h>
#include <glm/gtc/packing.hpp>

#include "render/scene_renderer.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

// A row of mature maples northward from the camera, one every 20 m, and one behind it.
Forest rowOfTrees(const TreeLibrary& library, int count) {
  Forest forest;
  const int type = library.typeIndex(1, 0, 1);
  const float height = library.types()[type].height_m;
  for (int i = 0; i < count; ++i)
    forest.add(library, type, worldFromMap(160, 26 + 20 * i, 100), height, 0.0f, 1.0f, i);
  forest.add(library, type, worldFromMap(160, 0, 100), height, 0.0f, 1.0f, 99);
  return forest;
}

TEST(ForestRenderer, CullsTreesOutsideTheViewAndCoarsensWithDistance) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(65, 10.0);
  FrameUniformBuffer uniforms;
  ForestRenderer renderer(library, {}, uniforms);
  const Forest forest = rowOfTrees(library, 30);
  Camera camera;
  camera.position = worldFromMap(160, 20, 105);  // looking north along the row
  const ForestStats stats = renderer.prepare(forest, camera, 640, 360, {}, {});
  EXPECT_EQ(stats.culled, 1u);  // the tree behind
  std::size_t drawn = 0;
  for (std::size_t n : stats.instances) drawn += n;
  EXPECT_GE(drawn, 30u);  // each tree at least once; cross-fading ones twice
  EXPECT_GT(stats.instances[0], 0u);
  EXPECT_GT(stats.instances[kLevelImpostor], 0u);
  EXPECT_LT(stats.triangles, stats.lod0Triangles);

  LodSettings allLod0;
  allLod0.forcedLevel = 0;
  const ForestStats lod0 = renderer.prepare(forest, camera, 640, 360, allLod0, {});
  EXPECT_EQ(lod0.instances[0], 30u);
  EXPECT_EQ(lod0.triangles, lod0.lod0Triangles);
  EXPECT_EQ(lod0.triangles, 30u * library.types()[forest.type[0]].meshes.lods[0].triangleCount());
}

TEST(ForestRenderer, OnlyMeshTreesInTheShadowBoxCastShadows) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  FrameUniformBuffer uniforms;
  ForestRenderer renderer(library, {}, uniforms);
  const Forest forest = rowOfTrees(library, 30);
  Camera camera;
  camera.position = worldFromMap(160, 20, 105);
  const ShadowBox box{worldFromMap(160, 60, 100), 50.0f};
  const ForestStats stats = renderer.prepare(forest, camera, 640, 360, {}, box);
  EXPECT_GT(stats.shadowCasters, 0u);
  EXPECT_LE(stats.shadowCasters, 6u);  // trees within 50 m (plus crown) of north 60
}

TEST(ForestRenderer, BlendingTreesDrawBothTypesAndAbsentTreesNothing) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  FrameUniformBuffer uniforms;
  ForestRenderer renderer(library, {}, uniforms);
  Forest forest = rowOfTrees(library, 3);
  Camera camera;
  camera.position = worldFromMap(160, 20, 105);
  LodSettings lod;
  lod.forcedLevel = 1;
  const auto drawn = [&] {
    const ForestStats stats = renderer.prepare(forest, camera, 640, 360, lod, {});
    return stats.instances[1];
  };
  EXPECT_EQ(drawn(), 3u);
  forest.blendType[0] = library.typeIndex(1, 0, 0);
  forest.blendWeight[0] = 0.4f;
  EXPECT_EQ(drawn(), 4u);  // the first tree as both age classes
  forest.presence[1] = 0.0f;
  EXPECT_EQ(drawn(), 3u);  // the second not at all
}

// A tree at presence p keeps about p of its pixels (dithered), whichever level draws it.
TEST(ForestRenderer, PresenceKeepsThatShareOfTheTreesPixels) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(33, 10.0);
  SceneRenderer scene(terrain, 46.0, &library);
  Forest forest;
  const int type = library.typeIndex(1, 0, 1);
  forest.add(library, type, worldFromMap(160, 160, 100), library.types()[type].height_m, 0.0f, 1.0f,
             1);
  Camera camera;
  camera.position = worldFromMap(160, 140, 100 + 0.5 * library.types()[type].height_m);
  RenderOptions options;
  options.shadows = false;
  const RenderTarget target = RenderTarget::create(96, 96);
  auto treePixels = [&](float presence) {
    Forest empty;
    scene.render(&empty, camera, options, target);
    const Image background = readPixels(96, 96);
    forest.presence[0] = presence;
    scene.render(&forest, camera, options, target);
    return test::compareImages(readPixels(96, 96), background).differingShare;
  };
  const double full = treePixels(1.0f);
  ASSERT_GT(full, 0.05);
  EXPECT_NEAR(treePixels(0.5f) / full, 0.5, 0.1);
  EXPECT_EQ(treePixels(0.0f), 0.0);
}

TEST(ForestRenderer, VariantsShareTheImpostorOfTheirSpeciesAndAgeClass) {
  test::useHeadlessGl();
  const TreeLibrary library({test::namedLibrarySpecies("shrub")},
                            LibrarySettings{.variants = 3, .ageClasses = {0.3, 1.0}});
  FrameUniformBuffer uniforms;
  ForestRenderer renderer(library, {}, uniforms);
  for (int v = 0; v < 3; ++v)
    for (int a = 0; a < 2; ++a)
      EXPECT_EQ(renderer.impostorSource(library.typeIndex(0, v, a)), library.typeIndex(0, 0, a));
}

TEST(ForestRenderer, PackedVerticesKeepPositionsExactlyAndTheRestClosely) {
  TreeVertex v{{1.25f, 20.5f, -3.0f}, glm::normalize(glm::vec3(0.3f, 0.9f, -0.2f)),
               {0.5f, 12.75f},        {0.01f, -0.2f, 0.3f},
               {1.5f, 0.0f, -0.75f},  {0.002f, 0.0f, 0.0f},
               {0.0f, 0.0f, 0.6f}};
  const PackedTreeVertex p = packVertex(v);
  EXPECT_EQ(p.position, v.position);
  EXPECT_EQ(p.uv, v.uv);
  const glm::vec4 normal = glm::unpackSnorm3x10_1x2(p.normal);
  EXPECT_LT(glm::distance(glm::vec3(normal), v.normal), 2e-3f);
  EXPECT_NEAR(glm::unpackHalf1x16(p.wind[1]), -0.2f, 1e-4f);
  EXPECT_NEAR(glm::unpackHalf1x16(p.wind[3]), 1.5f, 1e-3f);
  EXPECT_NEAR(glm::unpackHalf1x16(p.wind[11]), 0.6f, 1e-3f);
}

}  // namespace
}  // namespace eco
