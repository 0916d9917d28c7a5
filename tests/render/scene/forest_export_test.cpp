#include "render/scene/forest_export.hpp"

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <glm/gtc/quaternion.hpp>

#include "render/scene/camera.hpp"
#include "gltf_files.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

template <typename T>
std::vector<T> accessorValues(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& a = model.accessors[index];
  const tinygltf::BufferView& view = model.bufferViews[a.bufferView];
  const auto* data = reinterpret_cast<const T*>(model.buffers[view.buffer].data.data() +
                                                view.byteOffset + a.byteOffset);
  return std::vector<T>(data, data + a.count);
}

struct Scene {
  Terrain terrain = generateMidpoint({33, 0.5, 40.0}, 10.0, 12.0, 200.0, 3);
  Forest forest;
};

Scene smallScene() {
  Scene s;
  const TreeLibrary& library = test::smallLibrary();
  for (int i = 0; i < 25; ++i) {
    const double east = 20.0 + 11.0 * i, north = 300.0 - 9.0 * i;
    const int type = library.typeIndex(i % 2, 0, (i / 2) % 2);
    s.forest.add(library, type, worldFromMap(east, north, s.terrain.altitudeAt(east, north)),
                 3.0f + 0.5f * i, 0.0f, 0.8f, static_cast<std::uint64_t>(i));
  }
  return s;
}

TEST(ForestGltf, EveryTreeIsOneInstanceWithConsistentAccessors) {
  const Scene scene = smallScene();
  const auto file = test::freshDirectory("forest_gltf") / "forest.glb";
  const ForestGltfSummary summary =
      exportForest(scene.terrain, test::smallLibrary(), scene.forest, file);
  EXPECT_EQ(summary.instances, scene.forest.size());
  const tinygltf::Model model = test::loadGltf(file);
  EXPECT_EQ(model.extensionsRequired, std::vector<std::string>{"EXT_mesh_gpu_instancing"});
  std::size_t instances = 0;
  for (const tinygltf::Node& node : model.nodes) {
    if (!node.extensions.count("EXT_mesh_gpu_instancing")) continue;
    const tinygltf::Value& attributes =
        node.extensions.at("EXT_mesh_gpu_instancing").Get("attributes");
    const int translation = attributes.Get("TRANSLATION").GetNumberAsInt();
    const int rotation = attributes.Get("ROTATION").GetNumberAsInt();
    const int scale = attributes.Get("SCALE").GetNumberAsInt();
    const std::size_t count = model.accessors[translation].count;
    EXPECT_EQ(model.accessors[rotation].count, count);
    EXPECT_EQ(model.accessors[scale].count, count);
    for (const glm::vec4& q : accessorValues<glm::vec4>(model, rotation))
      EXPECT_NEAR(glm::length(q), 1.0f, 1e-5f);
    for (const glm::vec3& t : accessorValues<glm::vec3>(model, translation)) {
      // Each instance stands on the terrain.
      EXPECT_NEAR(t.y, groundBelow(scene.terrain, t), 1e-3f);
    }
    instances += count;
  }
  EXPECT_EQ(instances, scene.forest.size());
}

TEST(ForestGltf, TheTerrainsBoundingBoxIsTheHeightmaps) {
  const Scene scene = smallScene();
  const auto file = test::freshDirectory("forest_gltf_box") / "forest.gltf";
  exportForest(scene.terrain, test::smallLibrary(), scene.forest, file);
  const tinygltf::Model model = test::loadGltf(file);
  const tinygltf::Mesh& terrain = model.meshes[model.nodes[0].mesh];
  ASSERT_EQ(terrain.name, "terrain");
  const tinygltf::Accessor& positions =
      model.accessors[terrain.primitives[0].attributes.at("POSITION")];
  const FieldStats heights = statsOf(scene.terrain.height_m);
  const Grid& g = scene.terrain.grid;
  EXPECT_NEAR(positions.minValues[0], 0.0, 1e-4);
  EXPECT_NEAR(positions.maxValues[0], g.eastOf(g.width - 1), 1e-3);
  EXPECT_NEAR(positions.minValues[1], heights.min, 1e-3);
  EXPECT_NEAR(positions.maxValues[1], heights.max, 1e-3);
  EXPECT_NEAR(positions.minValues[2], -g.northOf(0), 1e-3);
  EXPECT_NEAR(positions.maxValues[2], 0.0, 1e-4);
}

// With every LOD, a type's node shows LOD0 and names its LOD1 and LOD2 nodes through
// MSFT_lod, each with the same instances and fewer triangles.
TEST(ForestGltf, AllLevelsOfDetailThroughMsftLod) {
  const Scene scene = smallScene();
  const auto file = test::freshDirectory("forest_gltf_lods") / "forest.glb";
  const ForestGltfSummary summary =
      exportForest(scene.terrain, test::smallLibrary(), scene.forest, file, kAllLods);
  const tinygltf::Model model = test::loadGltf(file);
  EXPECT_EQ(model.extensionsUsed,
            (std::vector<std::string>{"EXT_mesh_gpu_instancing", "MSFT_lod"}));
  auto triangles = [&](int node) {
    std::size_t count = 0;
    for (const tinygltf::Primitive& p : model.meshes[model.nodes[node].mesh].primitives)
      count += model.accessors[p.indices].count / 3;
    return count;
  };
  auto translations = [&](int node) {
    return model.nodes[node]
        .extensions.at("EXT_mesh_gpu_instancing")
        .Get("attributes")
        .Get("TRANSLATION")
        .GetNumberAsInt();
  };
  std::size_t withLods = 0;
  for (int root : model.scenes[0].nodes) {
    const tinygltf::Node& node = model.nodes[root];
    if (!node.extensions.count("MSFT_lod")) continue;
    ++withLods;
    const tinygltf::Value& ids = node.extensions.at("MSFT_lod").Get("ids");
    ASSERT_EQ(ids.ArrayLen(), 2u);
    int previous = root;
    for (std::size_t i = 0; i < 2; ++i) {
      const int lodNode = ids.Get(static_cast<int>(i)).GetNumberAsInt();
      EXPECT_LT(triangles(lodNode), triangles(previous));
      EXPECT_EQ(translations(lodNode), translations(root));
      previous = lodNode;
    }
    EXPECT_EQ(node.extras.Get("MSFT_screencoverage").ArrayLen(), 3u);
  }
  EXPECT_EQ(withLods, summary.treeMeshes);
}

// The instance rotation turns a tree as the renderer does (rotateYaw in common.glsl).
TEST(ForestGltf, InstanceRotationMatchesTheRenderersYaw) {
  Scene scene = smallScene();
  scene.forest.yaw[0] = 0.7f;
  const auto file = test::freshDirectory("forest_gltf_yaw") / "forest.glb";
  exportForest(scene.terrain, test::smallLibrary(), scene.forest, file);
  const tinygltf::Model model = test::loadGltf(file);
  for (const tinygltf::Node& node : model.nodes) {
    if (!node.extensions.count("EXT_mesh_gpu_instancing")) continue;
    const tinygltf::Value& attributes =
        node.extensions.at("EXT_mesh_gpu_instancing").Get("attributes");
    const auto translations =
        accessorValues<glm::vec3>(model, attributes.Get("TRANSLATION").GetNumberAsInt());
    if (translations[0] != scene.forest.position[0]) continue;
    const glm::vec4 q =
        accessorValues<glm::vec4>(model, attributes.Get("ROTATION").GetNumberAsInt())[0];
    const glm::vec3 turned = glm::quat(q.w, q.x, q.y, q.z) * glm::vec3(1, 0, 0);
    const float c = std::cos(0.7f), s = std::sin(0.7f);
    EXPECT_NEAR(glm::distance(turned, glm::vec3(c, 0, s)), 0.0f, 1e-5f);
    return;
  }
  FAIL() << "the first tree's instance was not found";
}

}  // namespace
}  // namespace eco
