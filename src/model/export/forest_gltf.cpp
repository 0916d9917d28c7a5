#include "model/export/forest_gltf.hpp"

#include <cmath>

#include <glm/vec4.hpp>

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

// EXT_mesh_gpu_instancing's attributes of a type's trees.
tinygltf::Value::Object addInstancing(GltfBuilder& builder, const ForestGltfType& type) {
  std::vector<glm::vec4> rotations;  // unit quaternions (x, y, z, w)
  for (float yaw : type.yaws_rad) {
    // The renderer turns x toward z by yaw: a rotation of -yaw about y.
    const float half = -0.5f * yaw;
    rotations.emplace_back(0.0f, std::sin(half), 0.0f, std::cos(half));
  }
  tinygltf::Value::Object attributes;
  attributes["TRANSLATION"] = tinygltf::Value(builder.addAccessor(
      type.translations, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 0, false));
  attributes["ROTATION"] = tinygltf::Value(builder.addAccessor(
      rotations, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, 0, false));
  attributes["SCALE"] = tinygltf::Value(builder.addAccessor(
      type.scales, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 0, false));
  tinygltf::Value::Object instancing;
  instancing["attributes"] = tinygltf::Value(attributes);
  return instancing;
}

// MSFT_screencoverage: the switching heights as fractions of the screen.
tinygltf::Value screenCoverage(const ForestGltfScene& scene) {
  tinygltf::Value::Array coverage;
  for (float pixels : scene.switchPixels)
    coverage.emplace_back(pixels / static_cast<double>(scene.screenHeight_px));
  tinygltf::Value::Object extras;
  extras["MSFT_screencoverage"] = tinygltf::Value(coverage);
  return tinygltf::Value(extras);
}

}  // namespace

ForestGltfSummary writeForestGltf(const ForestGltfScene& scene, const std::filesystem::path& file,
                                  int lod) {
  ForestGltfSummary summary;
  GltfBuilder builder;
  builder.useExtension("EXT_mesh_gpu_instancing", true);
  if (lod == kAllLods) builder.useExtension("MSFT_lod", false);
  std::vector<int> roots;

  summary.terrainTriangles = scene.terrain.triangleCount();
  roots.push_back(addTerrain(builder, scene.terrain));

  // Materials per species and kind, added when first used.
  std::vector<std::vector<int>> materials(scene.species.size(), std::vector<int>(5, -1));
  for (const ForestGltfType& type : scene.types) {
    if (type.translations.empty()) continue;
    const Species& species = *scene.species[type.species];
    auto meshOfLevel = [&](int level) {
      tinygltf::Mesh mesh;
      mesh.name = type.name + "_lod" + std::to_string(level);
      for (const MeshPart& part : type.lods[level].parts) {
        int& material = materials[type.species][static_cast<int>(part.material)];
        if (material < 0) material = builder.addMaterial(makeMaterial(part.material, species));
        builder.addPrimitive(mesh, part, material);
      }
      return builder.addMesh(std::move(mesh));
    };

    const tinygltf::Value::Object instancing = addInstancing(builder, type);

    auto instancedNode = [&](int level) {
      tinygltf::Node node;
      node.name = type.name + "_lod" + std::to_string(level);
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
      base.extras = screenCoverage(scene);
      roots.push_back(builder.addNode(std::move(base)));
    } else {
      roots.push_back(builder.addNode(instancedNode(lod)));
    }
    summary.instances += type.translations.size();
    ++summary.treeMeshes;
  }
  builder.setScene(std::move(roots));
  builder.write(file);
  return summary;
}

}  // namespace eco
