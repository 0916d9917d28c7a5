// The whole forest as one glTF 2.0 file for other tools (Blender, game engines): the terrain
// as a mesh, each tree type of the library as one mesh, and every tree as an instance of its
// type's mesh through EXT_mesh_gpu_instancing (translation, rotation, scale accessors). The
// frame is the renderer's — x east, y up, z south, metres — which is glTF's right-handed,
// y-up convention.
#pragma once

#include <cstddef>
#include <filesystem>

#include "render/forest.hpp"
#include "render/tree_library.hpp"
#include "sim/terrain.hpp"

namespace eco {

struct ForestGltfSummary {
  std::size_t instances = 0;
  std::size_t treeMeshes = 0;  // types with at least one tree
  std::size_t terrainTriangles = 0;
};

// Every level of detail: LOD0 as each type's mesh, LOD1 and LOD2 through MSFT_lod.
inline constexpr int kAllLods = -1;

// `lod` picks the level each type's mesh is exported at (0 full detail), or kAllLods for
// MSFT_lod: the type's node shows LOD0 and names two sibling nodes with LOD1 and LOD2 (the
// same instances), with the screen coverages at which the renderer switches
// (MSFT_screencoverage, fractions of a 720-pixel-high screen). Viewers without MSFT_lod
// show LOD0.
ForestGltfSummary writeForestGltf(const Terrain& terrain, const TreeLibrary& library,
                                  const Forest& forest, const std::filesystem::path& file,
                                  int lod = 1);

}  // namespace eco
