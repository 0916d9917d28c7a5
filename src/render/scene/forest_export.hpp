// The forest of a run for other tools: the terrain's triangles, the library's tree types at
// the chosen levels and the trees of the frame as their instances, each with its row of the
// trees CSV, written as glTF by model/export/forest_gltf.hpp.
#pragma once

#include <array>
#include <filesystem>
#include <vector>

#include <glm/vec2.hpp>

#include "core/image.hpp"
#include "model/export/forest_gltf.hpp"
#include "render/scene/forest.hpp"
#include "render/scene/impostor.hpp"
#include "render/scene/tree_library.hpp"
#include "sim/run/run_folder.hpp"
#include "sim/run/run_format.hpp"
#include "sim/terrain.hpp"

namespace eco {

// The billboard level: each type as two crossed quads showing it from the east and from
// the south, the two impostor frames nearest those horizontal directions (impostor.hpp),
// textured with those frames side by side (render/gl/billboards.hpp bakes them; east on
// the left). Each quad is the frame's orthographic view: the type's bounding sphere's
// square across the frame's right and up axes, facing its direction.
struct Billboards {
  ImpostorSettings settings;
  std::vector<Image> textures;  // [library type]
};
std::array<glm::ivec2, 2> billboardFrames(int frames);
TreeMesh billboardMesh(const TreeType& type, int frames);

// The scene as the glTF writer takes it. `rows` are the forest's trees in forest order (a
// forest built by forestFromSnapshot from those rows); `billboards` when
// options.billboards or options.lod is kBillboardLevel.
ForestGltfScene forestGltfScene(const Terrain& terrain, const TreeLibrary& library,
                                const Forest& forest, const std::vector<TreeRow>& rows,
                                const ForestGltfOptions& options,
                                const Billboards* billboards = nullptr);

// An InputError, before any forest is built, where options.maxTriangles cannot hold the
// terrain and every tree of the run's snapshot of `year` that `keep` keeps at the coarsest
// level the budget starts from (a billboard, or LOD2 without billboards): the types' trees
// are counted as the snapshot is read a batch of rows at a time, so a landscape is refused
// in the time it takes to read it, holding none of it. Nothing to check without a budget.
void requireBudgetReachable(const Terrain& terrain, const TreeLibrary& library,
                            const RunFolder& run, int year, const TreeFilter& keep,
                            const ForestGltfOptions& options);

// forestGltfScene written to `file` (.glb, or .gltf with STEM.bin beside it).
ForestGltfSummary exportForest(const Terrain& terrain, const TreeLibrary& library,
                               const Forest& forest, const std::vector<TreeRow>& rows,
                               const std::filesystem::path& file,
                               const ForestGltfOptions& options = {},
                               const Billboards* billboards = nullptr);

}  // namespace eco
