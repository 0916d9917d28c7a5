// The forest of a run for other tools: the terrain's triangles, the library's tree types at
// the chosen levels and the trees of the frame as their instances, each with its row of the
// trees CSV, written as glTF by model/export/forest_gltf.hpp.
#pragma once

#include <filesystem>
#include <vector>

#include "model/export/forest_gltf.hpp"
#include "render/scene/forest.hpp"
#include "render/scene/tree_library.hpp"
#include "sim/run/run_format.hpp"
#include "sim/terrain.hpp"

namespace eco {

// The scene as the glTF writer takes it. `rows` are the forest's trees in forest order (a
// forest built by forestFromSnapshot from those rows).
ForestGltfScene forestGltfScene(const Terrain& terrain, const TreeLibrary& library,
                                const Forest& forest, const std::vector<TreeRow>& rows,
                                const ForestGltfOptions& options);

// forestGltfScene written to `file` (.glb, or .gltf with STEM.bin beside it).
ForestGltfSummary exportForest(const Terrain& terrain, const TreeLibrary& library,
                               const Forest& forest, const std::vector<TreeRow>& rows,
                               const std::filesystem::path& file,
                               const ForestGltfOptions& options = {});

}  // namespace eco
