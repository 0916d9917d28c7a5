#include "model/export/forest_gltf.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "core/angles.hpp"
#include "gltf_files.hpp"
#include "test_support.hpp"

namespace eco {
namespace {

// A quad of terrain and one tree type of a few triangles, two trees of it, and one type
// without trees.
ForestGltfScene smallScene(const Species& species) {
  ForestGltfScene scene;
  scene.terrain.addVertex({0, 0, 0}, {0, 1, 0}, {0, 0});
  scene.terrain.addVertex({0, 0, 10}, {0, 1, 0}, {0, 1});
  scene.terrain.addVertex({10, 0, 0}, {0, 1, 0}, {1, 0});
  scene.terrain.addTriangle(0, 1, 2);
  scene.species = {&species};
  scene.switchPixels = {600.0f, 220.0f, 100.0f};
  scene.screenHeight_px = 720.0f;
  for (const char* name : {"one", "empty"}) {
    ForestGltfType& type = scene.types.emplace_back();
    type.name = name;
    for (TreeMesh& mesh : type.lods) {
      MeshPart& bark = mesh.parts.emplace_back();
      bark.addVertex({0, 0, 0}, {1, 0, 0}, {0, 0});
      bark.addVertex({0, 1, 0}, {1, 0, 0}, {0, 1});
      bark.addVertex({0, 0, 1}, {1, 0, 0}, {1, 0});
      bark.addTriangle(0, 1, 2);
    }
  }
  ForestGltfType& one = scene.types.front();
  one.translations = {{1, 2, 3}, {4, 5, 6}};
  one.yaws_rad = {0.0f, static_cast<float>(kPi / 2)};
  one.scales = {{1, 1, 1}, {2, 3, 2}};
  return scene;
}

TEST(ForestGltf, EachTreeIsAnInstanceTurnedByItsYaw) {
  const Species beech = test::loadNamed("beech");
  const auto file = test::freshDirectory("forest_gltf") / "forest.glb";
  const ForestGltfSummary summary = writeForestGltf(smallScene(beech), file, 1);
  EXPECT_EQ(summary.instances, 2u);
  EXPECT_EQ(summary.treeMeshes, 1u);  // the type without trees is left out
  EXPECT_EQ(summary.terrainTriangles, 1u);
  const tinygltf::Model model = test::loadGltf(file);
  ASSERT_EQ(model.nodes.size(), 2u);  // terrain, type "one"
  EXPECT_EQ(model.nodes[1].name, "one_lod1");
  const tinygltf::Value& attributes =
      model.nodes[1].extensions.at("EXT_mesh_gpu_instancing").Get("attributes");
  const tinygltf::Accessor& rotation = model.accessors[attributes.Get("ROTATION").GetNumberAsInt()];
  ASSERT_EQ(rotation.count, 2u);
  const tinygltf::BufferView& view = model.bufferViews[rotation.bufferView];
  const auto* q = reinterpret_cast<const float*>(model.buffers[view.buffer].data.data() +
                                                 view.byteOffset + rotation.byteOffset);
  // The second tree: a quarter turn of x toward z, -90 degrees about y.
  EXPECT_NEAR(q[4 + 1], -std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(q[4 + 3], std::sqrt(0.5f), 1e-6f);
}

TEST(ForestGltf, AllLevelsGoThroughMsftLodWithTheirScreenCoverages) {
  const Species beech = test::loadNamed("beech");
  const auto file = test::freshDirectory("forest_gltf_lods") / "forest.glb";
  writeForestGltf(smallScene(beech), file, kAllLods);
  const tinygltf::Model model = test::loadGltf(file);
  ASSERT_EQ(model.nodes.size(), 4u);  // terrain, LOD1, LOD2, then LOD0 naming them
  const tinygltf::Node& base = model.nodes.back();
  EXPECT_EQ(base.name, "one_lod0");
  EXPECT_EQ(base.extensions.at("MSFT_lod").Get("ids").ArrayLen(), 2u);
  const tinygltf::Value& coverage = base.extras.Get("MSFT_screencoverage");
  ASSERT_EQ(coverage.ArrayLen(), 3u);
  EXPECT_NEAR(coverage.Get(0).GetNumberAsDouble(), 600.0 / 720.0, 1e-9);
}

}  // namespace
}  // namespace eco
