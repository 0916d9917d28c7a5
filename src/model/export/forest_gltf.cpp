#include "model/export/forest_gltf.hpp"

#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <string_view>
#include <unordered_map>

#include <fmt/format.h>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "model/export/gltf_builder.hpp"

namespace eco {
namespace {

// The terrain's mesh and node, with a plain ground material.
int addTerrain(GltfBuilder& builder, const MeshPart& terrain) {
  Material ground;
  ground.name = "terrain";
  ground.baseColor = glm::vec4(0.30f, 0.36f, 0.18f, 1.0f);
  ground.roughness = 0.95f;
  tinygltf::Mesh mesh;
  mesh.name = "terrain";
  builder.addPrimitive(mesh, terrain, builder.addMaterial(ground));
  tinygltf::Node node;
  node.name = "terrain";
  node.mesh = builder.addMesh(std::move(mesh));
  return builder.addNode(std::move(node));
}

// The unit quaternion (x, y, z, w) of a tree's turn: the renderer turns x toward z by yaw,
// a rotation of -yaw about y; then the tilt turns the vertical toward its direction, about
// the horizontal axis up x direction.
glm::vec4 treeRotation(const ForestGltfTree& tree) {
  const glm::quat yaw = glm::angleAxis(-tree.yaw_rad, glm::vec3(0.0f, 1.0f, 0.0f));
  glm::quat q = yaw;
  if (const float angle = glm::length(tree.tilt_rad); angle > 0.0f) {
    const glm::vec3 axis = glm::normalize(
        glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(tree.tilt_rad.x, 0.0f, tree.tilt_rad.y)));
    q = glm::angleAxis(angle, axis) * yaw;
  }
  return {q.x, q.y, q.z, q.w};
}

// glTF accessors hold 32-bit integers at most.
std::uint32_t idOf(const ForestGltfTree& tree) {
  if (tree.id > std::numeric_limits<std::uint32_t>::max())
    throw InternalError("tree id " + std::to_string(tree.id) + " does not fit a glTF accessor");
  return static_cast<std::uint32_t>(tree.id);
}

template <typename T, typename Of>
int addPerTree(GltfBuilder& builder, const std::vector<ForestGltfTree>& trees, int componentType,
               int gltfType, Of of) {
  std::vector<T> values;
  values.reserve(trees.size());
  for (const ForestGltfTree& tree : trees) values.push_back(of(tree));
  return builder.addAccessor(values, componentType, gltfType, 0, false);
}

// EXT_mesh_gpu_instancing's attributes of a type's trees: the transforms and the trees'
// CSV columns.
tinygltf::Value::Object addInstancing(GltfBuilder& builder,
                                      const std::vector<ForestGltfTree>& trees, int species) {
  using Tree = ForestGltfTree;
  constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
  constexpr int kScalar = TINYGLTF_TYPE_SCALAR;
  tinygltf::Value::Object attributes;
  auto add = [&](const char* name, int accessor) { attributes[name] = tinygltf::Value(accessor); };
  add("TRANSLATION", addPerTree<glm::vec3>(builder, trees, kFloat, TINYGLTF_TYPE_VEC3,
                                           [](const Tree& t) { return t.translation; }));
  add("ROTATION", addPerTree<glm::vec4>(builder, trees, kFloat, TINYGLTF_TYPE_VEC4,
                                        [](const Tree& t) { return treeRotation(t); }));
  add("SCALE", addPerTree<glm::vec3>(builder, trees, kFloat, TINYGLTF_TYPE_VEC3,
                                     [](const Tree& t) { return t.scale; }));
  add("_ID", addPerTree<std::uint32_t>(builder, trees, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                       kScalar, idOf));
  add("_SPECIES",
      addPerTree<std::uint16_t>(builder, trees, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, kScalar,
                                [&](const Tree&) { return std::uint16_t(species); }));
  add("_AGE", addPerTree<float>(builder, trees, kFloat, kScalar,
                                [](const Tree& t) { return t.age_years; }));
  add("_HEIGHT",
      addPerTree<float>(builder, trees, kFloat, kScalar, [](const Tree& t) { return t.height_m; }));
  add("_DBH",
      addPerTree<float>(builder, trees, kFloat, kScalar, [](const Tree& t) { return t.dbh_m; }));
  add("_VIGOR",
      addPerTree<float>(builder, trees, kFloat, kScalar, [](const Tree& t) { return t.vigor; }));
  tinygltf::Value::Object instancing;
  instancing["attributes"] = tinygltf::Value(attributes);
  return instancing;
}

// A tree's own node (Instancing::Nodes) as JSON: its transform, and its CSV row as extras,
// which Blender shows as the object's custom properties. Written as text because tinygltf's
// objects would cost kilobytes a tree (gigabytes for a valley). `species` is the name as a
// JSON string's inside (escaped, without quotes). Floats print as the shortest text that
// reads back to the same float.
void appendTreeNode(std::string& out, const ForestGltfTree& tree, std::string_view species,
                    int mesh) {
  const glm::vec4 q = treeRotation(tree);
  const glm::vec3 t = tree.translation, s = tree.scale;
  // Ids past a 32-bit int as a real number: readers such as tinygltf parse integers into int.
  const std::string id = tree.id <= static_cast<std::uint64_t>(std::numeric_limits<int>::max())
                             ? std::to_string(tree.id)
                             : std::to_string(tree.id) + ".0";
  if (!out.empty()) out += ',';
  fmt::format_to(std::back_inserter(out),
                 "{{\"name\":\"{}_{}\",\"mesh\":{},\"translation\":[{},{},{}],"
                 "\"rotation\":[{},{},{},{}],\"scale\":[{},{},{}],\"extras\":{{\"id\":{},"
                 "\"species\":\"{}\",\"age\":{},\"height_m\":{},\"dbh_m\":{},\"vigor\":{}}}}}",
                 species, tree.id, mesh, t.x, t.y, t.z, q.x, q.y, q.z, q.w, s.x, s.y, s.z, id,
                 species, static_cast<int>(tree.age_years), tree.height_m, tree.dbh_m, tree.vigor);
}

void addWindAttributes(GltfBuilder& builder, tinygltf::Primitive& primitive,
                       const WindBases& wind) {
  auto add = [&](const char* name, const std::vector<glm::vec3>& values) {
    primitive.attributes[name] =
        builder.addAccessor(values, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                            TINYGLTF_TARGET_ARRAY_BUFFER, false);
  };
  add("_SWAY_SIN", wind.swaySin);
  add("_SWAY_COS", wind.swayCos);
  add("_BEND_EAST", wind.bendEast);
  add("_BEND_SOUTH", wind.bendSouth);
}

// A billboard's material: its own pictures of the tree, cut out where they are empty, seen
// from both sides.
Material billboardMaterial(const ForestGltfType& type, const Image& texture) {
  Material m;
  m.name = type.name + "_billboard";  // the first type showing these pictures
  m.texture = texture;
  m.alphaMask = true;
  m.doubleSided = true;
  m.roughness = 0.9f;
  return m;
}

// MSFT_screencoverage: the least share of the screen's height each level is shown at, the
// renderer's switching heights; a billboard, the last level, at any size.
tinygltf::Value screenCoverage(const ForestGltfScene& scene, bool billboards) {
  tinygltf::Value::Array coverage;
  for (float pixels : scene.switchPixels)
    coverage.emplace_back(pixels / static_cast<double>(scene.screenHeight_px));
  if (billboards) coverage.emplace_back(0.0);
  tinygltf::Value::Object extras;
  extras["MSFT_screencoverage"] = tinygltf::Value(coverage);
  return tinygltf::Value(extras);
}

// The scene's extras: the species names that _SPECIES indexes.
tinygltf::Value speciesNames(const ForestGltfScene& scene) {
  tinygltf::Value::Array names;
  for (const Species* species : scene.species) names.emplace_back(species->name);
  tinygltf::Value::Object extras;
  extras["species"] = tinygltf::Value(names);
  return tinygltf::Value(extras);
}

}  // namespace

ForestGltfSummary writeForestGltf(const ForestGltfScene& scene, const std::filesystem::path& file,
                                  const ForestGltfOptions& options) {
  const bool gpu = options.instancing == Instancing::Gpu;
  if (options.lod == kAllLods && !gpu)
    throw InternalError("MSFT_lod levels are written for GPU instancing only");
  ForestGltfSummary summary;
  GltfBuilder builder;
  if (gpu) builder.useExtension("EXT_mesh_gpu_instancing", true);
  if (options.lod == kAllLods) builder.useExtension("MSFT_lod", false);
  std::vector<int> roots;

  summary.terrainTriangles = scene.terrain.triangleCount();
  roots.push_back(addTerrain(builder, scene.terrain));

  // Materials per species and kind, added when first used; billboards' by their pictures.
  std::vector<std::vector<int>> materials(scene.species.size(), std::vector<int>(5, -1));
  std::unordered_map<std::uint64_t, int> billboardMaterials;
  std::string treeNodes;  // Instancing::Nodes: each tree's node as JSON
  std::size_t treeNodeCount = 0;
  for (const ForestGltfType& type : scene.types) {
    if (type.trees.empty()) continue;
    const Species& species = *scene.species[type.species];
    auto meshOfLevel = [&](int level) {
      tinygltf::Mesh mesh;
      mesh.name = type.name + "_lod" + std::to_string(level);
      const std::vector<MeshPart>& parts = type.lods[level].parts;
      if (level == kBillboardLevel) {
        if (!type.billboardTexture || parts.size() != 1)
          throw InternalError("tree type " + type.name + " has no billboard to export");
        // Variants that share their pictures (the renderer's impostors) share one material.
        const std::string_view bytes(
            reinterpret_cast<const char*>(type.billboardTexture->rgba.data()),
            type.billboardTexture->rgba.size());
        auto [material, added] = billboardMaterials.try_emplace(fnv1a64(bytes), -1);
        if (added)
          material->second = builder.addMaterial(billboardMaterial(type, *type.billboardTexture));
        builder.addPrimitive(mesh, parts[0], material->second);
        return builder.addMesh(std::move(mesh));
      }
      if (options.wind && type.wind[level].size() != parts.size())
        throw InternalError("tree type " + type.name + " has no wind bases to export");
      for (std::size_t p = 0; p < parts.size(); ++p) {
        const MeshPart& part = parts[p];
        int& material = materials[type.species][static_cast<int>(part.material)];
        if (material < 0) material = builder.addMaterial(makeMaterial(part.material, species));
        builder.addPrimitive(mesh, part, material);
        if (options.wind) addWindAttributes(builder, mesh.primitives.back(), type.wind[level][p]);
      }
      return builder.addMesh(std::move(mesh));
    };

    // Each level's mesh, written when a tree first uses it.
    std::array<int, kExportLevels> meshes;
    meshes.fill(-1);
    auto meshAt = [&](int level) {
      if (meshes[level] < 0) meshes[level] = meshOfLevel(level);
      return meshes[level];
    };
    auto levelOf = [&](const ForestGltfTree& tree) {
      return tree.level >= 0 ? tree.level : options.lod;
    };

    if (!gpu) {
      const std::string name = nlohmann::json(species.name).dump();  // quoted and escaped
      const std::string_view inner(name.data() + 1, name.size() - 2);
      for (const ForestGltfTree& tree : type.trees)
        appendTreeNode(treeNodes, tree, inner, meshAt(levelOf(tree)));
      treeNodeCount += type.trees.size();
    } else if (options.lod == kAllLods) {
      const tinygltf::Value::Object instancing = addInstancing(builder, type.trees, type.species);
      auto instancedNode = [&](int level) {
        tinygltf::Node node;
        node.name = type.name + "_lod" + std::to_string(level);
        node.mesh = meshAt(level);
        node.extensions["EXT_mesh_gpu_instancing"] = tinygltf::Value(instancing);
        return node;
      };
      tinygltf::Node base = instancedNode(0);
      tinygltf::Value::Array ids;
      const int levels = options.billboards ? kExportLevels : kLodCount;
      for (int level = 1; level < levels; ++level)
        ids.emplace_back(builder.addNode(instancedNode(level)));
      tinygltf::Value::Object msftLod;
      msftLod["ids"] = tinygltf::Value(ids);
      base.extensions["MSFT_lod"] = tinygltf::Value(msftLod);
      base.extras = screenCoverage(scene, options.billboards);
      roots.push_back(builder.addNode(std::move(base)));
    } else {
      // One instanced node per level the type's trees are drawn at.
      for (int level = 0; level < kExportLevels; ++level) {
        std::vector<ForestGltfTree> trees;
        for (const ForestGltfTree& tree : type.trees)
          if (levelOf(tree) == level) trees.push_back(tree);
        if (trees.empty()) continue;
        tinygltf::Node node;
        node.name = type.name + "_lod" + std::to_string(level);
        node.mesh = meshAt(level);
        node.extensions["EXT_mesh_gpu_instancing"] =
            tinygltf::Value(addInstancing(builder, trees, type.species));
        roots.push_back(builder.addNode(std::move(node)));
      }
    }
    for (const ForestGltfTree& tree : type.trees) {
      const int level = options.lod == kAllLods ? 0 : levelOf(tree);
      ++summary.treesAtLevel[level];
      summary.treeTriangles += type.lods[level].triangleCount();
    }
    summary.instances += type.trees.size();
    ++summary.treeMeshes;
  }
  // The trees' own nodes come after every other node (GltfBuilder::addRootNodesJson).
  builder.setScene(std::move(roots), speciesNames(scene));
  builder.addRootNodesJson(treeNodes, treeNodeCount);
  builder.write(file);
  return summary;
}

}  // namespace eco
