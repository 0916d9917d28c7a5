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

// forestGltfScene written to `file` (.glb, or .gltf with STEM.bin beside it).
ForestGltfSummary exportForest(const Terrain& terrain, const TreeLibrary& library,
                               const Forest& forest, const std::vector<TreeRow>& rows,
                               const std::filesystem::path& file,
                               const ForestGltfOptions& options = {},
                               const Billboards* billboards = nullptr);

}  // namespace eco
