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
    for (int level = 0; level < kLodCount; ++level) {  // the model's levels
      MeshPart& bark = type.lods[level].parts.emplace_back();
      bark.addVertex({0, 0, 0}, {1, 0, 0}, {0, 0});
      bark.addVertex({0, 1, 0}, {1, 0, 0}, {0, 1});
      bark.addVertex({0, 0, 1}, {1, 0, 0}, {1, 0});
      bark.addTriangle(0, 1, 2);
    }
  }
  ForestGltfType& one = scene.types.front();
  one.trees = {{.translation = {1, 2, 3}, .id = 7, .age_years = 30, .height_m = 12.5f},
               {.translation = {4, 5, 6},
                .yaw_rad = static_cast<float>(kPi / 2),
                .scale = {2, 3, 2},
                .id = 4000000000u,
                .age_years = 80,
                .height_m = 31.25f,
                .dbh_m = 0.5f,
                .vigor = 0.75f}};
  return scene;
}

template <typename T>
std::vector<T> accessorValues(const tinygltf::Model& model, const tinygltf::Value& index) {
  const tinygltf::Accessor& a = model.accessors[index.GetNumberAsInt()];
  const tinygltf::BufferView& view = model.bufferViews[a.bufferView];
  const auto* data = reinterpret_cast<const T*>(model.buffers[view.buffer].data.data() +
                                                view.byteOffset + a.byteOffset);
  return std::vector<T>(data, data + a.count);
}

const ForestGltfOptions kGpu{.instancing = Instancing::Gpu};

TEST(ForestGltf, EachTreeIsAnInstanceTurnedByItsYaw) {
  const Species beech = test::loadNamed("beech");
  const auto file = test::freshDirectory("forest_gltf") / "forest.glb";
  const ForestGltfSummary summary = writeForestGltf(smallScene(beech), file, kGpu);
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

TEST(ForestGltf, GpuInstancesCarryTheirTreesAttributes) {
  const Species beech = test::loadNamed("beech");
  const auto file = test::freshDirectory("forest_gltf_attributes") / "forest.glb";
  writeForestGltf(smallScene(beech), file, kGpu);
  const tinygltf::Model model = test::loadGltf(file);
  const tinygltf::Value& a =
      model.nodes[1].extensions.at("EXT_mesh_gpu_instancing").Get("attributes");
  EXPECT_EQ(accessorValues<std::uint32_t>(model, a.Get("_ID")),
            (std::vector<std::uint32_t>{7u, 4000000000u}));
  EXPECT_EQ(accessorValues<std::uint16_t>(model, a.Get("_SPECIES")),
            (std::vector<std::uint16_t>{0, 0}));
  EXPECT_EQ(accessorValues<float>(model, a.Get("_AGE")), (std::vector<float>{30, 80}));
  EXPECT_EQ(accessorValues<float>(model, a.Get("_HEIGHT")), (std::vector<float>{12.5f, 31.25f}));
  EXPECT_EQ(accessorValues<float>(model, a.Get("_DBH")), (std::vector<float>{0.0f, 0.5f}));
  EXPECT_EQ(accessorValues<float>(model, a.Get("_VIGOR")), (std::vector<float>{0.0f, 0.75f}));
  // _SPECIES indexes the scene's list of names.
  EXPECT_EQ(model.scenes[0].extras.Get("species").Get(0).Get<std::string>(), "beech");
}

TEST(ForestGltf, NodesGiveEachTreeItsOwnNodeSharingTheTypesMesh) {
  const Species beech = test::loadNamed("beech");
  const auto file = test::freshDirectory("forest_gltf_nodes") / "forest.gltf";
  const ForestGltfSummary summary = writeForestGltf(smallScene(beech), file, {});
  EXPECT_EQ(summary.instances, 2u);
  const tinygltf::Model model = test::loadGltf(file);
  EXPECT_TRUE(model.extensionsUsed.empty());
  ASSERT_EQ(model.nodes.size(), 3u);  // terrain and the two trees
  const tinygltf::Node& first = model.nodes[1];
  const tinygltf::Node& second = model.nodes[2];
  EXPECT_EQ(first.mesh, second.mesh);
  EXPECT_EQ(model.meshes.size(), 2u);  // terrain, the type's LOD1
  EXPECT_EQ(first.name, "beech_7");
  EXPECT_EQ(first.translation, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(second.scale, (std::vector<double>{2, 3, 2}));
  EXPECT_NEAR(second.rotation[1], -std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(second.rotation[3], std::sqrt(0.5), 1e-6);
  EXPECT_EQ(first.extras.Get("id").GetNumberAsInt(), 7);
  EXPECT_EQ(first.extras.Get("species").Get<std::string>(), "beech");
  EXPECT_EQ(first.extras.Get("age").GetNumberAsInt(), 30);
  EXPECT_EQ(second.extras.Get("id").GetNumberAsDouble(), 4000000000.0);
  EXPECT_EQ(second.extras.Get("height_m").GetNumberAsDouble(), 31.25);
  EXPECT_EQ(second.extras.Get("dbh_m").GetNumberAsDouble(), 0.5);
  EXPECT_EQ(second.extras.Get("vigor").GetNumberAsDouble(), 0.75);
}

// The billboard level: its own material with the pictures, cut out and double-sided; in
// MSFT_lod the last level, shown at any size.
TEST(ForestGltf, BillboardsHaveTheirOwnPicturesAndAreTheLastLevel) {
  const Species beech = test::loadNamed("beech");
  ForestGltfScene scene = smallScene(beech);
  for (ForestGltfType& type : scene.types) {
    MeshPart& quad = type.lods[kBillboardLevel].parts.emplace_back();
    quad.addVertex({0, 0, 0}, {0, 0, 1}, {0, 1});
    quad.addVertex({1, 0, 0}, {0, 0, 1}, {1, 1});
    quad.addVertex({1, 1, 0}, {0, 0, 1}, {1, 0});
    quad.addTriangle(0, 1, 2);
    type.billboardTexture = Image(4, 2);
  }
  const auto dir = test::freshDirectory("forest_gltf_billboards");
  writeForestGltf(scene, dir / "b.glb", {.lod = kBillboardLevel});
  const tinygltf::Model model = test::loadGltf(dir / "b.glb");
  const tinygltf::Material& material = model.materials.back();
  EXPECT_EQ(material.name, "one_billboard");
  EXPECT_EQ(material.alphaMode, "MASK");
  EXPECT_TRUE(material.doubleSided);
  EXPECT_GE(material.pbrMetallicRoughness.baseColorTexture.index, 0);
  EXPECT_EQ(model.nodes[1].mesh, model.nodes[2].mesh);  // both trees on the billboard mesh
  EXPECT_EQ(model.meshes[model.nodes[1].mesh].name, "one_lod3");

  writeForestGltf(scene, dir / "all.glb",
                  {.instancing = Instancing::Gpu, .lod = kAllLods, .billboards = true});
  const tinygltf::Model all = test::loadGltf(dir / "all.glb");
  const tinygltf::Node& base = all.nodes.back();
  EXPECT_EQ(base.extensions.at("MSFT_lod").Get("ids").ArrayLen(), 3u);
  const tinygltf::Value& coverage = base.extras.Get("MSFT_screencoverage");
  ASSERT_EQ(coverage.ArrayLen(), 4u);
  EXPECT_EQ(coverage.Get(3).GetNumberAsDouble(), 0.0);
}

// A .gltf keeps its bytes in STEM.bin beside it rather than as base64 inside the JSON.
TEST(ForestGltf, TextGltfKeepsItsBufferInABinFile) {
  const Species beech = test::loadNamed("beech");
  const auto dir = test::freshDirectory("forest_gltf_bin");
  writeForestGltf(smallScene(beech), dir / "forest.gltf", {});
  ASSERT_TRUE(std::filesystem::exists(dir / "forest.bin"));
  const tinygltf::Model model = test::loadGltf(dir / "forest.gltf");
  ASSERT_EQ(model.buffers.size(), 1u);
  EXPECT_EQ(model.buffers[0].uri, "forest.bin");
  EXPECT_EQ(model.buffers[0].data.size(), std::filesystem::file_size(dir / "forest.bin"));
  EXPECT_EQ(test::entriesIn(dir), 2u);  // no temporaries left
}

TEST(ForestGltf, AllLevelsGoThroughMsftLodWithTheirScreenCoverages) {
  const Species beech = test::loadNamed("beech");
  const auto file = test::freshDirectory("forest_gltf_lods") / "forest.glb";
  writeForestGltf(smallScene(beech), file, {.instancing = Instancing::Gpu, .lod = kAllLods});
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
