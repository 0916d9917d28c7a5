#include "render/scene/forest_export.hpp"

#include "core/frames.hpp"
#include "render/scene/culling.hpp"
#include "render/scene/frame_size.hpp"
#include "sim/terrain_mesh.hpp"

namespace eco {
namespace {

// The terrain as one mesh part: vertices at the cell centres, the terrain's normals.
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

TreeMesh treeMesh(const WindMesh& wind) {
  TreeMesh mesh;
  for (const WindPart& windPart : wind.parts) {
    MeshPart& part = mesh.parts.emplace_back();
    part.material = windPart.material;
    part.reserve(windPart.vertices.size(), windPart.indices.size() / 3);
    for (const TreeVertex& v : windPart.vertices) part.addVertex(v.position, v.normal, v.uv);
    part.indices.assign(windPart.indices.begin(), windPart.indices.end());
  }
  return mesh;
}

}  // namespace

ForestGltfScene forestGltfScene(const Terrain& terrain, const TreeLibrary& library,
                                const Forest& forest, int lod) {
  ForestGltfScene scene;
  scene.terrain = terrainPart(terrain);
  for (const Species& s : library.species()) scene.species.push_back(&s);
  const LodSettings switching;
  std::copy(switching.switchPixels.begin(), switching.switchPixels.end(),
            scene.switchPixels.begin());
  scene.screenHeight_px = static_cast<float>(FrameSize{}.height);  // the frames' default
  // The trees of each type, in forest order.
  const auto& types = library.types();
  std::vector<std::vector<std::size_t>> members(types.size());
  for (std::size_t i = 0; i < forest.size(); ++i) members[forest.type[i]].push_back(i);
  for (std::size_t t = 0; t < types.size(); ++t) {
    if (members[t].empty()) continue;
    const TreeType& type = types[t];
    ForestGltfType& out = scene.types.emplace_back();
    out.name = library.species()[type.species].name + "_variant" + std::to_string(type.variant) +
               "_age" + std::to_string(type.ageClass);
    out.species = type.species;
    for (int level = 0; level < kLodCount; ++level)
      if (lod == kAllLods || lod == level) out.lods[level] = treeMesh(type.meshes.lods[level]);
    for (std::size_t i : members[t]) {
      out.translations.push_back(forest.position[i]);
      out.yaws_rad.push_back(forest.yaw[i]);
      out.scales.emplace_back(forest.scaleXZ[i], forest.scaleY[i], forest.scaleXZ[i]);
    }
  }
  return scene;
}

ForestGltfSummary exportForest(const Terrain& terrain, const TreeLibrary& library,
                               const Forest& forest, const std::filesystem::path& file, int lod) {
  return writeForestGltf(forestGltfScene(terrain, library, forest, lod), file, lod);
}

}  // namespace eco
