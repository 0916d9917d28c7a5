// A whole forest as one glTF 2.0 file for other tools (Blender, game engines): the terrain
// as a mesh, each tree type as one mesh shared by its trees, and every tree either as its
// own node (Instancing::Nodes: what every importer reads) or as an instance of its type's
// node through EXT_mesh_gpu_instancing (Instancing::Gpu: one draw per type in engines that
// read the extension). Each tree carries its row of the trees CSV: node extras, or
// per-instance attributes (_ID, _SPECIES, _AGE, _HEIGHT, _DBH, _VIGOR). The frame is the
// world frame (core/frames.hpp: x east, y up, z south, metres), glTF's right-handed, y-up
// convention. The renderer's scene (render/scene/forest_export.hpp) fills it from a run.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/image.hpp"
#include "model/mesh/lod.hpp"
#include "model/mesh/mesh.hpp"
#include "model/species.hpp"

namespace eco {

// One tree: where it stands and how its type's mesh is turned and scaled, and what its row
// of the trees CSV says about it.
struct ForestGltfTree {
  glm::vec3 translation{0.0f};  // stem base
  float yaw_rad = 0.0f;         // turn of x toward z about the vertical
  // The site's lean as a rigid tilt about the stem base, after the yaw: toward (x east,
  // z south), by its length in radians.
  glm::vec2 tilt_rad{0.0f};
  glm::vec3 scale{1.0f};
  std::uint64_t id = 0;
  float age_years = 0.0f, height_m = 0.0f, dbh_m = 0.0f, vigor = 0.0f;
  int level = -1;  // the level of detail it is drawn at; -1: ForestGltfOptions::lod
};

// The wind bases of a mesh part's vertices (the renderer's, docs/rendering.md), in the
// tree's frame: at wind time t a vertex at rest p is drawn at
//   p + w_s (sin t swaySin + cos t swayCos) + w_g (d_east bendEast + d_south bendSouth)
// for a sway strength w_s (degrees per metre) and a horizontal wind of strength w_g toward
// the unit direction (d_east, d_south); exported as _SWAY_SIN, _SWAY_COS, _BEND_EAST and
// _BEND_SOUTH vertex attributes for an engine's vertex shader.
struct WindBases {
  std::vector<glm::vec3> swaySin, swayCos, bendEast, bendSouth;
};

// The levels a tree can be exported at: the model's LOD0-LOD2 and, past them, a billboard
// of crossed quads textured with pictures of the tree (the far level engines use).
inline constexpr int kBillboardLevel = kLodCount;
inline constexpr int kExportLevels = kLodCount + 1;

// One tree type: its meshes and every tree drawn with it.
struct ForestGltfType {
  std::string name;
  int species = 0;  // index into ForestGltfScene::species
  // The levels exported (others may stay empty); the billboard's one part is drawn with
  // `billboardTexture` (sRGB with alpha, cut out at half), not a material of the species.
  std::array<TreeMesh, kExportLevels> lods;
  std::optional<Image> billboardTexture;
  // Per level, one entry per part of the mesh; empty: no wind data (billboards never sway).
  std::array<std::vector<WindBases>, kExportLevels> wind;
  std::vector<ForestGltfTree> trees;
};

struct ForestGltfScene {
  MeshPart terrain;
  std::vector<const Species*> species;  // their names and materials
  std::vector<ForestGltfType> types;    // in the order they are written
  // For MSFT_lod: the heights in pixels at which a viewer switches to LOD1, LOD2 and past
  // LOD2, and the screen height they are measured on.
  std::array<float, 3> switchPixels{};
  float screenHeight_px = 0.0f;
};

enum class Instancing {
  Nodes,  // one node per tree sharing its type's mesh: Blender, assimp, every viewer
  Gpu,    // EXT_mesh_gpu_instancing, required: three.js, Babylon.js, engines
};

// Every level of detail: LOD0 as each type's mesh, LOD1 and LOD2 through MSFT_lod.
inline constexpr int kAllLods = -1;

struct ForestGltfOptions {
  Instancing instancing = Instancing::Nodes;
  // The level each type's mesh is exported at (0 full detail, kBillboardLevel), or kAllLods
  // (Gpu only): the type's node shows LOD0 and names sibling nodes with LOD1, LOD2 and,
  // with `billboards`, the billboard (the same instances), with the screen coverages at
  // which to switch (MSFT_screencoverage). Viewers without MSFT_lod show LOD0.
  int lod = 1;
  bool billboards = false;  // the types carry billboards: kAllLods and maxTriangles use them
  bool wind = false;        // the wind bases as vertex attributes (the types must carry them)
  // A budget for the scene's triangles (terrain and every tree as drawn): each tree's level
  // is chosen by its height (render/scene/forest_export.hpp); 0: no budget, `lod` for all.
  std::size_t maxTriangles = 0;
};

struct ForestGltfSummary {
  std::size_t instances = 0;
  std::size_t treeMeshes = 0;  // types with at least one tree
  std::size_t terrainTriangles = 0;
  std::size_t treeTriangles = 0;  // of every tree as drawn (at LOD0 with MSFT_lod)
  std::array<std::size_t, kExportLevels> treesAtLevel{};
};

// Types without trees are left out. The per-instance attribute names, as EXT_mesh_gpu_
// instancing requires of custom ones, start with an underscore.
ForestGltfSummary writeForestGltf(const ForestGltfScene& scene, const std::filesystem::path& file,
                                  const ForestGltfOptions& options);

}  // namespace eco
