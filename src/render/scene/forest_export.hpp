// The forest of a run for other tools: the terrain's triangles, the library's tree types at
// the chosen levels and the trees of the frame as their instances, written as glTF by
// model/forest_gltf.hpp.
#pragma once

#include <filesystem>

#include "model/export/forest_gltf.hpp"
#include "render/scene/forest.hpp"
#include "render/scene/tree_library.hpp"
#include "sim/terrain.hpp"

namespace eco {

// The scene as the glTF writer takes it. `lod` is a level or kAllLods.
ForestGltfScene forestGltfScene(const Terrain& terrain, const TreeLibrary& library,
                                const Forest& forest, int lod);

// forestGltfScene written to `file` (.glb or .gltf).
ForestGltfSummary exportForest(const Terrain& terrain, const TreeLibrary& library,
                               const Forest& forest, const std::filesystem::path& file,
                               int lod = 1);

}  // namespace eco
