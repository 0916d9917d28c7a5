#include "render/scene/forest_export.hpp"

#include <optional>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <glm/gtc/quaternion.hpp>

#include "gltf_files.hpp"
#include "render/scene/camera.hpp"
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
  std::vector<TreeRow> rows;  // what the trees CSV says of each tree
};

const ForestGltfOptions kGpu{.instancing = Instancing::Gpu};

Scene smallScene() {
  Scene s;
  const TreeLibrary& library = test::smallLibrary();
  for (int i = 0; i < 25; ++i) {
    const double east = 20.0 + 11.0 * i, north = 300.0 - 9.0 * i;
    const int type = library.typeIndex(i % 2, 0, (i / 2) % 2);
    const float height = 3.0f + 0.5f * i;
    s.forest.add(library, type, worldFromMap(east, north, s.terrain.altitudeAt(east, north)),
                 height, 0.0f, 0.8f, static_cast<std::uint64_t>(i));
    s.rows.push_back({.id = 100u + i,
                      .age_years = 5 + i,
                      .height_m = height,
                      .dbh_m = 0.01f * i,
                      .vigor = 0.8f});
  }
  return s;
}

TEST(ForestGltf, EveryTreeIsOneInstanceWithConsistentAccessors) {
  const Scene scene = smallScene();
  const auto file = test::freshDirectory("forest_gltf") / "forest.glb";
  const ForestGltfSummary summary =
      exportForest(scene.terrain, test::smallLibrary(), scene.forest, scene.rows, file, kGpu);
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

// Each tree's node (the default) stands where its instance would, with its row's values.
TEST(ForestGltf, NodesAreTheTreesWithTheirRows) {
  const Scene scene = smallScene();
  const auto file = test::freshDirectory("forest_gltf_nodes") / "forest.glb";
  exportForest(scene.terrain, test::smallLibrary(), scene.forest, scene.rows, file);
  const tinygltf::Model model = test::loadGltf(file);
  EXPECT_TRUE(model.extensionsRequired.empty());
  std::size_t trees = 0;
  for (const tinygltf::Node& node : model.nodes) {
    if (!node.extras.Has("id")) continue;
    const auto i = static_cast<std::size_t>(node.extras.Get("id").GetNumberAsInt() - 100);
    ASSERT_LT(i, scene.rows.size());
    EXPECT_EQ(node.extras.Get("age").GetNumberAsInt(), scene.rows[i].age_years);
    EXPECT_FLOAT_EQ(static_cast<float>(node.extras.Get("dbh_m").GetNumberAsDouble()),
                    scene.rows[i].dbh_m);
    EXPECT_FLOAT_EQ(static_cast<float>(node.translation[1]), scene.forest.position[i].y);
    EXPECT_FLOAT_EQ(static_cast<float>(node.scale[1]), scene.forest.scaleY[i]);
    ++trees;
  }
  EXPECT_EQ(trees, scene.forest.size());
}

// With wind, each primitive carries its part's four wind bases, vertex for vertex.
TEST(ForestGltf, WindBasesAreVertexAttributesOfEveryTreePrimitive) {
  const Scene scene = smallScene();
  const auto file = test::freshDirectory("forest_gltf_wind") / "forest.glb";
  exportForest(scene.terrain, test::smallLibrary(), scene.forest, scene.rows, file,
               {.lod = 1, .wind = true});
  const tinygltf::Model model = test::loadGltf(file);
  const TreeType& type = test::smallLibrary().type(scene.forest.type[0]);
  std::size_t primitives = 0;
  bool swaying = false;
  for (const tinygltf::Mesh& mesh : model.meshes) {
    if (mesh.name == "terrain") continue;
    for (const tinygltf::Primitive& p : mesh.primitives) {
      const std::size_t vertices = model.accessors[p.attributes.at("POSITION")].count;
      for (const char* name : {"_SWAY_SIN", "_SWAY_COS", "_BEND_EAST", "_BEND_SOUTH"}) {
        ASSERT_TRUE(p.attributes.count(name)) << name;
        EXPECT_EQ(model.accessors[p.attributes.at(name)].count, vertices);
      }
      for (const glm::vec3& v : accessorValues<glm::vec3>(model, p.attributes.at("_SWAY_SIN")))
        swaying |= glm::length(v) > 0.0f;
      ++primitives;
    }
  }
  EXPECT_GT(primitives, 0u);
  EXPECT_TRUE(swaying);  // branches and leaves move
  // The first tree's type: its bases are the wind mesh's.
  const std::string name = test::smallLibrary().species()[type.species].name + "_variant" +
                           std::to_string(type.variant) + "_age" + std::to_string(type.ageClass) +
                           "_lod1";
  for (const tinygltf::Mesh& mesh : model.meshes) {
    if (mesh.name != name) continue;
    const WindPart& part = type.meshes.lods[1].parts[0];
    const auto bends =
        accessorValues<glm::vec3>(model, mesh.primitives[0].attributes.at("_BEND_EAST"));
    ASSERT_EQ(bends.size(), part.vertices.size());
    for (std::size_t i = 0; i < bends.size(); ++i) EXPECT_EQ(bends[i], part.vertices[i].bendEast);
    return;
  }
  FAIL() << "no mesh " << name;
}

// Under a triangle budget the scene stays within it, taller trees get at least the detail
// of shorter ones, and a budget too small even for LOD2 is refused.
TEST(ForestGltf, ATriangleBudgetGoesToTheTallestTreesFirst) {
  const Scene scene = smallScene();
  const TreeLibrary& library = test::smallLibrary();
  const ForestGltfScene coarse =
      forestGltfScene(scene.terrain, library, scene.forest, scene.rows, {.lod = 2});
  const ForestGltfScene fine =
      forestGltfScene(scene.terrain, library, scene.forest, scene.rows, {.lod = 0});
  // The scene's triangles; `lod` for trees without a level of their own.
  auto total = [](const ForestGltfScene& s, int lod) {
    std::size_t n = s.terrain.triangleCount();
    for (const ForestGltfType& t : s.types)
      for (const ForestGltfTree& tree : t.trees)
        n += t.lods[tree.level >= 0 ? tree.level : lod].triangleCount();
    return n;
  };
  const std::size_t budget = (total(coarse, 2) + total(fine, 0)) / 2;
  const ForestGltfScene chosen =
      forestGltfScene(scene.terrain, library, scene.forest, scene.rows, {.maxTriangles = budget});
  EXPECT_LE(total(chosen, -1), budget);
  std::vector<std::pair<float, int>> levels;  // (height, level)
  for (const ForestGltfType& t : chosen.types)
    for (const ForestGltfTree& tree : t.trees) levels.emplace_back(tree.height_m, tree.level);
  std::sort(levels.begin(), levels.end(), std::greater<>());
  EXPECT_EQ(levels.front().second, 0);  // the tallest in full detail
  EXPECT_GT(levels.back().second, 0);   // the shortest coarser
  for (std::size_t i = 1; i < levels.size(); ++i) EXPECT_GE(levels[i].second, levels[i - 1].second);
  // The file holds what was chosen.
  const auto file = test::freshDirectory("forest_gltf_budget") / "forest.glb";
  const ForestGltfSummary summary = exportForest(scene.terrain, library, scene.forest, scene.rows,
                                                 file, {.maxTriangles = budget});
  EXPECT_EQ(summary.treeTriangles + summary.terrainTriangles, total(chosen, -1));
  try {
    forestGltfScene(scene.terrain, library, scene.forest, scene.rows,
                    {.maxTriangles = total(coarse, 2) - 1});
    FAIL() << "a budget under every tree at LOD2 was taken";
  } catch (const InputError& e) {  // says what to do: fewer plants, or billboards
    EXPECT_NE(std::string(e.what()).find("--min-height, or add --billboards"), std::string::npos)
        << e.what();
  }
}

// A budget is checked against a run's snapshot before any forest is built: the same count
// as the scene's at the coarsest level, of the plants the filter keeps, with billboards too.
TEST(ForestGltf, ABudgetIsCheckedAgainstTheSnapshotBeforeTheForestIsBuilt) {
  const Terrain terrain = smallScene().terrain;
  const TreeLibrary& library = test::smallLibrary();
  TreeSnapshot snapshot;
  snapshot.year = 7;
  snapshot.speciesNames = {"maple", "beech"};
  for (std::uint64_t id = 1; id <= 200; ++id) {
    snapshot.trees.push_back(test::variedTree(id));
    snapshot.trees.back().species = static_cast<int>(id % 2);
  }
  const RunFolder run =
      test::runHolding("forest_gltf_budget_check", {&snapshot}, SnapshotFormat::Binary);
  // The fewest triangles of the scene the export would build of the rows `keep` keeps.
  auto fewest = [&](const TreeFilter& keep, bool billboards) {
    const TreeSnapshot kept = readSnapshot(run, snapshot.year, keep);
    const Forest forest = forestFromSnapshot(kept, library, "run");
    const ForestGltfScene scene =
        forestGltfScene(terrain, library, forest, kept.trees, {.lod = billboards ? 1 : 2});
    std::size_t n = scene.terrain.triangleCount();
    for (const ForestGltfType& t : scene.types)
      n += t.trees.size() * (billboards ? billboardMesh(library.type(0), 8).triangleCount()
                                        : t.lods[2].triangleCount());
    return n;
  };
  const TreeFilter tall = [](const TreeRow& tree) { return tree.height_m >= 15.0f; };
  for (const bool billboards : {false, true})
    for (const TreeFilter& keep : {TreeFilter{}, tall}) {
      const std::size_t least = fewest(keep, billboards);
      const ForestGltfOptions enough{.billboards = billboards, .maxTriangles = least};
      EXPECT_NO_THROW(requireBudgetReachable(terrain, library, run, snapshot.year, keep, enough));
      ForestGltfOptions under = enough;
      --under.maxTriangles;
      try {
        requireBudgetReachable(terrain, library, run, snapshot.year, keep, under);
        ADD_FAILURE() << "a budget of " << under.maxTriangles << " was taken";
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(std::to_string(least) + " triangles"),
                  std::string::npos)
            << e.what();
      }
    }
  EXPECT_LT(fewest(tall, false), fewest({}, false));  // the filter counts
  // Under the terrain's own triangles no choice of trees helps, and the error says so.
  const TreeFilter none = [](const TreeRow&) { return false; };
  try {
    requireBudgetReachable(terrain, library, run, snapshot.year, none, {.maxTriangles = 3});
    ADD_FAILURE() << "a budget under the terrain was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the terrain alone takes"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(requireBudgetReachable(terrain, library, run, snapshot.year, {}, {}));
}

// Two crossed quads, each the square of the type's bounding sphere across its frame's axes,
// facing its direction: east's frame on the left half of the picture, south's on the right.
TEST(ForestGltf, ABillboardIsTwoQuadsFacingTheirFrames) {
  EXPECT_EQ(billboardFrames(8), (std::array<glm::ivec2, 2>{glm::ivec2(7, 7), glm::ivec2(7, 0)}));
  const TreeType& type = test::smallLibrary().type(0);
  const TreeMesh mesh = billboardMesh(type, 8);
  ASSERT_EQ(mesh.parts.size(), 1u);
  const MeshPart& quads = mesh.parts[0];
  ASSERT_EQ(quads.positions.size(), 8u);
  EXPECT_EQ(quads.triangleCount(), 4u);
  for (int view = 0; view < 2; ++view) {
    const glm::vec3 f = frameDirection(billboardFrames(8)[view], 8);
    EXPECT_GT(view == 0 ? f.x : f.z, 0.95f);  // nearly horizontal, toward east or south
    for (int corner = 0; corner < 4; ++corner) {
      const std::size_t v = 4 * view + corner;
      EXPECT_EQ(quads.normals[v], f);
      // On the plane through the sphere's centre, at its radius from it along both axes.
      const glm::vec3 offset = quads.positions[v] - glm::vec3(type.bounds);
      EXPECT_NEAR(glm::dot(offset, f), 0.0f, 1e-4f);
      EXPECT_NEAR(glm::length(offset), std::sqrt(2.0f) * type.bounds.w, 1e-3f);
      EXPECT_GE(quads.uvs[v].x, 0.5f * view);  // its half of the picture
      EXPECT_LE(quads.uvs[v].x, 0.5f * (view + 1));
    }
  }
  // Triangles face the view they show.
  for (std::size_t t = 0; t < quads.indices.size(); t += 3) {
    const glm::vec3 a = quads.positions[quads.indices[t]],
                    b = quads.positions[quads.indices[t + 1]],
                    c = quads.positions[quads.indices[t + 2]];
    EXPECT_GT(glm::dot(glm::cross(b - a, c - a), quads.normals[quads.indices[t]]), 0.0f);
  }
}

TEST(ForestGltf, TheTerrainsBoundingBoxIsTheHeightmaps) {
  const Scene scene = smallScene();
  const auto file = test::freshDirectory("forest_gltf_box") / "forest.gltf";
  exportForest(scene.terrain, test::smallLibrary(), scene.forest, scene.rows, file, kGpu);
  const tinygltf::Model model = test::loadGltf(file);
  const tinygltf::Mesh& terrain = model.meshes[model.nodes[0].mesh];
  ASSERT_EQ(terrain.name, "terrain");
  const tinygltf::Accessor& positions =
      model.accessors[terrain.primitives[0].attributes.at("POSITION")];
  const FieldStats heights = statsOf(scene.terrain.height_m);
  const Grid& g = scene.terrain.grid;
  // Out to the edge cells' outer sides (the rim), where the plants of those cells stand.
  EXPECT_NEAR(positions.minValues[0], -0.5 * g.dx_m, 1e-4);
  EXPECT_NEAR(positions.maxValues[0], g.eastOf(g.width - 1) + 0.5 * g.dx_m, 1e-3);
  EXPECT_NEAR(positions.minValues[1], heights.min, 1e-3);
  EXPECT_NEAR(positions.maxValues[1], heights.max, 1e-3);
  EXPECT_NEAR(positions.minValues[2], -g.northOf(0) - 0.5 * g.dy_m, 1e-3);
  EXPECT_NEAR(positions.maxValues[2], 0.5 * g.dy_m, 1e-4);
}

// With every LOD, a type's node shows LOD0 and names its LOD1 and LOD2 nodes through
// MSFT_lod, each with the same instances and fewer triangles.
TEST(ForestGltf, AllLevelsOfDetailThroughMsftLod) {
  const Scene scene = smallScene();
  const auto file = test::freshDirectory("forest_gltf_lods") / "forest.glb";
  const ForestGltfSummary summary =
      exportForest(scene.terrain, test::smallLibrary(), scene.forest, scene.rows, file,
                   {.instancing = Instancing::Gpu, .lod = kAllLods});
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

// The scene exported with GPU instancing into a fresh folder, and the instance rotation of
// its first tree as written; nullopt if its instance is not found.
std::optional<glm::quat> exportedRotationOfFirstTree(const Scene& scene,
                                                     const std::string& folder) {
  const auto file = test::freshDirectory(folder) / "forest.glb";
  exportForest(scene.terrain, test::smallLibrary(), scene.forest, scene.rows, file, kGpu);
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
    return glm::quat(q.w, q.x, q.y, q.z);
  }
  return std::nullopt;
}

// The instance rotation turns a tree as the renderer does (rotateYaw in common.glsl).
TEST(ForestGltf, InstanceRotationMatchesTheRenderersYaw) {
  Scene scene = smallScene();
  scene.forest.yaw[0] = 0.7f;
  const std::optional<glm::quat> rotation = exportedRotationOfFirstTree(scene, "forest_gltf_yaw");
  ASSERT_TRUE(rotation) << "the first tree's instance was not found";
  const glm::vec3 turned = *rotation * glm::vec3(1, 0, 0);
  const float c = std::cos(0.7f), s = std::sin(0.7f);
  EXPECT_NEAR(glm::distance(turned, glm::vec3(c, 0, s)), 0.0f, 1e-5f);
}

// A glTF node cannot bend: a leaning tree tilts toward its lean, and an upright one does not.
TEST(ForestGltf, ALeaningTreeTiltsTowardItsLean) {
  Scene scene = smallScene();
  scene.forest.yaw[0] = 0.7f;
  scene.forest.lean[0] = glm::vec2(2.0f, 0.0f);  // twice the bases toward east
  const ForestGltfScene gltf =
      forestGltfScene(scene.terrain, test::smallLibrary(), scene.forest, scene.rows, kGpu);
  float tilt = 0.0f;
  for (const ForestGltfType& type : gltf.types)
    for (const ForestGltfTree& tree : type.trees) {
      if (tree.id != scene.rows[0].id) {
        EXPECT_EQ(tree.tilt_rad, glm::vec2(0.0f));
        continue;
      }
      tilt = tree.tilt_rad.x;
      EXPECT_EQ(tree.tilt_rad.y, 0.0f);
    }
  EXPECT_GT(tilt, 0.02f);
  EXPECT_LT(tilt, 0.5f);

  const std::optional<glm::quat> rotation = exportedRotationOfFirstTree(scene, "forest_gltf_tilt");
  ASSERT_TRUE(rotation) << "the first tree's instance was not found";
  const glm::vec3 up = *rotation * glm::vec3(0, 1, 0);
  EXPECT_NEAR(std::atan2(up.x, up.y), tilt, 1e-5f);  // the stem leans east by the tilt
  EXPECT_NEAR(up.z, 0.0f, 1e-5f);
}

}  // namespace
}  // namespace eco
