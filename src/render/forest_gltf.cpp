#include "render/forest_gltf.hpp"

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "model/gltf_builder.hpp"
#include "render/camera.hpp"
#include "render/culling.hpp"
#include "render/terrain_renderer.hpp"
#include "sim/terrain_mesh.hpp"

namespace eco {
namespace {

// The terrain as one mesh part: vertices at the cell centres, smooth normals.
MeshPart terrainPart(const Terrain& terrain) {
  const Grid& g = terrain.grid;
  MeshPart part;
  part.material = MaterialKind::Bark;  // unused: the terrain has its own material
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x)
      part.addVertex(worldFromMap(cellPosition(terrain, x, y)),
                     worldDirectionFromMap(terrainNormal(terrain, x, y)),
                     {(x + 0.5f) / g.width, (y + 0.5f) / g.height});
  const std::vector<std::uint32_t> triangles = terrainTriangles(g);
  part.indices.assign(triangles.begin(), triangles.end());
  return part;
}

MeshPart meshPart(const WindPart& wind) {
  MeshPart part;
  part.material = wind.material;
  part.reserve(wind.vertices.size(), wind.indices.size() / 3);
  for (const TreeVertex& v : wind.vertices) part.addVertex(v.position, v.normal, v.uv);
  part.indices.assign(wind.indices.begin(), wind.indices.end());
  return part;
}

}  // namespace

ForestGltfSummary writeForestGltf(const Terrain& terrain, const TreeLibrary& library,
                                  const Forest& forest, const std::filesystem::path& file,
                                  int lod) {
  ForestGltfSummary summary;
  GltfBuilder builder;
  builder.useExtension("EXT_mesh_gpu_instancing", true);
  if (lod == kAllLods) builder.useExtension("MSFT_lod", false);
  std::vector<int> roots;

  Material ground;
  ground.name = "terrain";
  ground.baseColor = glm::vec4(0.30f, 0.36f, 0.18f, 1.0f);
  ground.roughness = 0.95f;
  const MeshPart groundPart = terrainPart(terrain);
  summary.terrainTriangles = groundPart.triangleCount();
  tinygltf::Mesh terrainMesh;
  terrainMesh.name = "terrain";
  builder.addPrimitive(terrainMesh, groundPart, builder.addMaterial(ground));
  tinygltf::Node terrainNode;
  terrainNode.name = "terrain";
  terrainNode.mesh = builder.addMesh(std::move(terrainMesh));
  roots.push_back(builder.addNode(std::move(terrainNode)));

  // The trees of each type, in forest order.
  const auto& types = library.types();
  std::vector<std::vector<std::size_t>> members(types.size());
  for (std::size_t i = 0; i < forest.size(); ++i) members[forest.type[i]].push_back(i);

  // Materials per species and kind, added when first used.
  std::vector<std::vector<int>> materials(library.species().size(), std::vector<int>(5, -1));
  for (std::size_t t = 0; t < types.size(); ++t) {
    if (members[t].empty()) continue;
    const TreeType& type = types[t];
    const Species& species = library.species()[type.species];
    const std::string name = species.name + "_variant" + std::to_string(type.variant) + "_age" +
                             std::to_string(type.ageClass);
    auto meshOfLevel = [&](int level) {
      tinygltf::Mesh mesh;
      mesh.name = name + "_lod" + std::to_string(level);
      for (const WindPart& part : type.meshes.lods[level].parts) {
        int& material = materials[type.species][static_cast<int>(part.material)];
        if (material < 0) material = builder.addMaterial(makeMaterial(part.material, species));
        builder.addPrimitive(mesh, meshPart(part), material);
      }
      return builder.addMesh(std::move(mesh));
    };

    std::vector<glm::vec3> translations, scales;
    std::vector<glm::vec4> rotations;  // unit quaternions (x, y, z, w)
    for (std::size_t i : members[t]) {
      translations.push_back(forest.position[i]);
      // The renderer turns x toward z by yaw: a rotation of -yaw about y.
      const float half = -0.5f * forest.yaw[i];
      rotations.emplace_back(0.0f, std::sin(half), 0.0f, std::cos(half));
      scales.emplace_back(forest.scaleXZ[i], forest.scaleY[i], forest.scaleXZ[i]);
    }
    tinygltf::Value::Object attributes;
    attributes["TRANSLATION"] = tinygltf::Value(builder.addAccessor(
        translations, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 0, false));
    attributes["ROTATION"] = tinygltf::Value(builder.addAccessor(
        rotations, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, 0, false));
    attributes["SCALE"] = tinygltf::Value(
        builder.addAccessor(scales, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 0, false));
    tinygltf::Value::Object instancing;
    instancing["attributes"] = tinygltf::Value(attributes);

    auto instancedNode = [&](int level) {
      tinygltf::Node node;
      node.name = name + "_lod" + std::to_string(level);
      node.mesh = meshOfLevel(level);
      node.extensions["EXT_mesh_gpu_instancing"] = tinygltf::Value(instancing);
      return node;
    };
    if (lod == kAllLods) {
      tinygltf::Node base = instancedNode(0);
      tinygltf::Value::Array ids;
      for (int level = 1; level < kLodCount; ++level)
        ids.emplace_back(builder.addNode(instancedNode(level)));
      tinygltf::Value::Object msftLod;
      msftLod["ids"] = tinygltf::Value(ids);
      base.extensions["MSFT_lod"] = tinygltf::Value(msftLod);
      tinygltf::Value::Array coverage;
      for (float pixels : LodSettings{}.switchPixels) coverage.emplace_back(pixels / 720.0);
      tinygltf::Value::Object extras;
      extras["MSFT_screencoverage"] = tinygltf::Value(coverage);
      base.extras = tinygltf::Value(extras);
      roots.push_back(builder.addNode(std::move(base)));
    } else {
      roots.push_back(builder.addNode(instancedNode(lod)));
    }
    summary.instances += members[t].size();
    ++summary.treeMeshes;
  }
  builder.setScene(std::move(roots));
  builder.write(file);
  return summary;
}

}  // namespace eco
