#include "render/scene/design_preview.hpp"

#include <utility>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/frames.hpp"
#include "model/tree_generator.hpp"
#include "render/scene/culling.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

std::size_t vertexCount(const WindMesh& mesh) {
  std::size_t n = 0;
  for (const WindPart& part : mesh.parts) n += part.vertices.size();
  return n;
}

}  // namespace

TEST(DesignPreview, TheEditedTreeIsTheModelsTreeAtTheLevelAskedFor) {
  const Species beech = test::loadNamedSpecies("beech");
  PreviewSettings settings;
  settings.seed = 3;
  settings.age = 0.8;
  settings.level = 1;
  const PreviewScene scene = buildPreview(beech, settings);
  ASSERT_EQ(scene.types.size(), static_cast<std::size_t>(kPreviewRowFirst));
  EXPECT_FALSE(scene.complete);
  const TreeType& edited = scene.types[kPreviewEdited];
  EXPECT_EQ(edited.seed, 3u);
  const TreeSkeleton tree = buildTree(beech, windBuildOptions(beech, 3, 0.8, {}, 0.0));
  const SkeletonMeasures m = measure(tree);
  EXPECT_EQ(scene.stats.segments, m.segments);
  EXPECT_EQ(scene.stats.leaves, tree.leaves.size());
  EXPECT_DOUBLE_EQ(scene.stats.height_m, m.height_m);
  EXPECT_EQ(edited.meshes.lods[1].triangleCount(), buildLod(tree, beech, 1).triangleCount());
  EXPECT_EQ(scene.stats.triangles, edited.meshes.lods[1].triangleCount());
  EXPECT_TRUE(edited.meshes.lods[0].parts.empty());  // only the level shown is built
  EXPECT_TRUE(scene.types[kPreviewHint].meshes.lods[1].parts.empty());  // no hint asked for
  EXPECT_GT(scene.stats.buildMs, 0.0);
}

// Shown as an impostor, a tree builds the level its frames are baked from: LOD1 for a
// broadleaf, LOD0 for a species that bears needles (impostorBakeLevel), as the renderer
// bakes them.
TEST(DesignPreview, AnImpostorBuildsTheLevelItsFramesAreBakedFrom) {
  PreviewSettings settings;
  settings.level = kLevelImpostor;
  settings.age = 0.4;
  for (const auto& [name, level] : {std::pair{"beech", 1}, std::pair{"pine", 0}}) {
    SCOPED_TRACE(name);
    const PreviewScene scene = buildPreview(test::loadNamedSpecies(name), settings);
    const TreeType& edited = scene.types[kPreviewEdited];
    EXPECT_GT(edited.meshes.lods[level].triangleCount(), 0u);
    EXPECT_TRUE(edited.meshes.lods[1 - level].parts.empty());
    EXPECT_EQ(scene.stats.triangles, edited.meshes.lods[level].triangleCount());
  }
}

TEST(DesignPreview, TheHintSleevesTheSegmentsOfTheEditedOrders) {
  const Species beech = test::loadNamedSpecies("beech");
  PreviewSettings settings;
  settings.hint = HintInterval{LocalGraph::AlphaG, 1.5, 2.5, true};  // g = 2
  const PreviewScene scene = buildPreview(beech, settings);
  const TreeSkeleton tree = buildTree(beech, windBuildOptions(beech, 1, 1.0, {}, 0.0));
  const std::size_t hinted = hintedSegments(tree, *settings.hint).size();
  ASSERT_GT(hinted, 0u);
  // Six sides, two rings per hinted segment.
  EXPECT_EQ(vertexCount(scene.types[kPreviewHint].meshes.lods[0]), 12 * hinted);
  EXPECT_EQ(scene.types[kPreviewHint].species, kPreviewHint);
  const std::vector<Species> species = previewSpecies(beech, {});
  EXPECT_EQ(species[kPreviewHint].appearance.barkColor, kHintColor);
  EXPECT_EQ(species[kPreviewEdited].appearance.barkColor, beech.appearance.barkColor);
}

TEST(DesignPreview, TheRowStandsEastOfTheTreeWithoutTouchingCrowns) {
  const Species beech = test::loadNamedSpecies("beech");
  const Species pine = test::loadNamedSpecies("pine");
  PreviewScene scene = buildPreview(beech, {});
  addPreviewRow(scene, beech, {pine});
  ASSERT_EQ(scene.types.size(), static_cast<std::size_t>(previewTypeCount(1)));
  ASSERT_EQ(scene.bases.size(), scene.types.size());
  EXPECT_TRUE(scene.complete);
  EXPECT_EQ(scene.bases[kPreviewHint], scene.bases[kPreviewEdited]);
  // Younger ages of the same seed, then other seeds, then the pine.
  EXPECT_EQ(scene.types[kPreviewRowFirst].age, kPreviewRowAges[0]);
  EXPECT_EQ(scene.types[kPreviewRowFirst].seed, 1u);
  EXPECT_EQ(scene.types[kPreviewRowFirst + 3].seed, 2u);
  EXPECT_EQ(scene.types.back().species, kPreviewComparedSpeciesFirst);
  std::vector<int> row = {kPreviewEdited};
  for (int t = kPreviewRowFirst; t < static_cast<int>(scene.types.size()); ++t) row.push_back(t);
  for (std::size_t i = 1; i < row.size(); ++i) {
    const glm::vec3 a = scene.bases[row[i - 1]], b = scene.bases[row[i]];
    EXPECT_GT(b.x, a.x);
    EXPECT_EQ(b.z, a.z);
    EXPECT_GE(b.x - a.x, scene.types[row[i - 1]].crownRadius_m + scene.types[row[i]].crownRadius_m);
  }
  const Terrain ground = previewGround(scene.bases);
  for (const glm::vec3& base : scene.bases)
    EXPECT_GE(ground.grid.cellAt(mapFromWorld(base).x, mapFromWorld(base).y), 0);
  EXPECT_EQ(previewForest(scene.bases, true, true).size(), scene.bases.size());
  EXPECT_EQ(previewForest(scene.bases, false, true).size(), scene.bases.size() - 1);
  EXPECT_EQ(previewForest(scene.bases, false, false).size(), 1u);
}

TEST(DesignPreview, TheOrbitCameraLooksAtItsTarget) {
  OrbitCamera orbit;
  orbit.target = {10.0f, 5.0f, -3.0f};
  orbit.distance_m = 20.0f;
  orbit.yaw_deg = 30.0f;
  orbit.pitch_deg = 25.0f;
  const Camera camera = orbit.camera();
  EXPECT_NEAR(glm::distance(camera.position, orbit.target), 20.0f, 1e-4f);
  EXPECT_NEAR(glm::dot(glm::normalize(orbit.target - camera.position), camera.forward()), 1.0f,
              1e-5f);
  EXPECT_GT(camera.position.y, orbit.target.y);  // above, looking down
  orbit.zoom(1.0f);
  EXPECT_LT(orbit.distance_m, 20.0f);
  orbit.orbit(100.0f, 1e6f);
  EXPECT_LE(orbit.pitch_deg, 85.0f);
}

TEST(DesignPreview, TheBuilderDeliversTheNewestRequestComplete) {
  const Species beech = test::loadNamedSpecies("beech");
  PreviewBuilder builder({});
  Species edited = beech;
  for (std::uint64_t version = 1; version <= 3; ++version) {
    edited.strand.kc = 0.2 * static_cast<double>(version);
    builder.request(edited, version, {});
  }
  std::optional<PreviewScene> last;
  for (int i = 0; i < 500 && (!last || !last->complete || last->version != 3); ++i)
    if (std::optional<PreviewScene> scene = builder.take(std::chrono::milliseconds(20)))
      last = std::move(scene);
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(last->version, 3u);
  EXPECT_TRUE(last->complete);
  // The same as building it here: the worker is deterministic.
  const PreviewScene here = buildCompletePreview(edited, {}, {});
  EXPECT_EQ(last->stats.segments, here.stats.segments);
  EXPECT_EQ(last->bases, here.bases);
  EXPECT_EQ(last->types[kPreviewEdited].meshes.lods[0].triangleCount(),
            here.types[kPreviewEdited].meshes.lods[0].triangleCount());
  EXPECT_FALSE(builder.busy());
  // A tree built within 10 ms is worth waiting for within a frame, a slower one not.
  EXPECT_GT(builder.lastBuildMs(), 0.0);
  EXPECT_EQ(builder.worthWaiting(),
            std::chrono::milliseconds(builder.lastBuildMs() < 10.0 ? 12 : 0));
}

}  // namespace eco
