// A whole forest as one glTF 2.0 file for other tools (Blender, game engines): the terrain
// as a mesh, each tree type as one mesh, and every tree as an instance of its type's mesh
// through EXT_mesh_gpu_instancing (translation, rotation, scale accessors). The frame is the
// world frame (core/frames.hpp: x east, y up, z south, metres), glTF's right-handed, y-up
// convention. The renderer's scene (render/scene/forest_export.hpp) fills it from a run.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "model/mesh/lod.hpp"
#include "model/mesh/mesh.hpp"
#include "model/species.hpp"

namespace eco {

// One tree type: its meshes and every tree drawn with it.
struct ForestGltfType {
  std::string name;
  int species = 0;                       // index into ForestGltfScene::species
  std::array<TreeMesh, kLodCount> lods;  // the levels exported (others may stay empty)
  std::vector<glm::vec3> translations;   // stem bases
  std::vector<float> yaws_rad;           // turns of x toward z about the vertical
  std::vector<glm::vec3> scales;
};

struct ForestGltfScene {
  MeshPart terrain;
  std::vector<const Species*> species;  // their materials
  std::vector<ForestGltfType> types;    // in the order they are written
  // For MSFT_lod: the heights in pixels at which a viewer switches to LOD1, LOD2 and past
  // LOD2, and the screen height they are measured on.
  std::array<float, 3> switchPixels{};
  float screenHeight_px = 0.0f;
};

struct ForestGltfSummary {
  std::size_t instances = 0;
  std::size_t treeMeshes = 0;  // types with at least one tree
  std::size_t terrainTriangles = 0;
};

// Every level of detail: LOD0 as each type's mesh, LOD1 and LOD2 through MSFT_lod.
inline constexpr int kAllLods = -1;

// `lod` picks the level each type's mesh is exported at (0 full detail), or kAllLods for
// MSFT_lod: the type's node shows LOD0 and names two sibling nodes with LOD1 and LOD2 (the
// same instances), with the screen coverages at which to switch (MSFT_screencoverage).
// Viewers without MSFT_lod show LOD0. Types without trees are left out.
ForestGltfSummary writeForestGltf(const ForestGltfScene& scene, const std::filesystem::path& file,
                                  int lod);

}  // namespace eco
