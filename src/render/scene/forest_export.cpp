#include "render/scene/forest_export.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "core/frames.hpp"
#include "render/scene/culling.hpp"
#include "render/scene/frame_size.hpp"
#include "sim/terrain_mesh.hpp"

namespace eco {
namespace {

// The terrain as one mesh part: vertices at the cell centres and its rim out to the cells'
// edges, the terrain's normals.
MeshPart terrainPart(const Terrain& terrain) {
  const Grid& g = terrain.grid;
  MeshPart part;
  part.material = MaterialKind::Bark;  // unused: the terrain has its own material
  const TerrainRim rim = terrainRim(g);
  for (const DrawnVertex& v : drawnTerrainVertices(terrain, rim))
    part.addVertex(worldFromMap(v.position), worldDirectionFromMap(v.normal), v.mapUv);
  const std::vector<std::uint32_t> triangles = terrainTriangles(g);
  part.indices.assign(triangles.begin(), triangles.end());
  part.indices.insert(part.indices.end(), rim.triangles.begin(), rim.triangles.end());
  return part;
}

WindBases windBases(const WindPart& part) {
  WindBases bases;
  for (const TreeVertex& v : part.vertices) {
    bases.swaySin.push_back(v.swaySin);
    bases.swayCos.push_back(v.swayCos);
    bases.bendEast.push_back(v.bendEast);
    bases.bendSouth.push_back(v.bendSouth);
  }
  return bases;
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

// An InputError unless the terrain (`terrain` triangles) and every tree at the coarsest level
// (`used` triangles with the terrain's) fit the budget, saying how to make them fit.
void requireWithinBudget(std::size_t terrain, std::size_t used, std::size_t maxTriangles,
                         bool billboards) {
  if (used <= maxTriangles) return;
  if (terrain > maxTriangles)  // no choice of trees helps
    throw InputError(
        {"export", 0, "--max-triangles"},
        fmt::format("the terrain alone takes {} triangles, more than {}", terrain, maxTriangles));
  throw InputError(
      {"export", 0, "--max-triangles"},
      fmt::format("the terrain and every tree {} already take {} triangles, more than {}: "
                  "leave the smaller plants out with --min-height{}",
                  billboards ? "as a billboard" : "at LOD2", used, maxTriangles,
                  billboards ? "" : ", or add --billboards (4 triangles a tree)"));
}

// Each tree's level under a triangle budget. Every tree starts at the coarsest level (the
// billboard, or LOD2 without billboards); then level by level toward LOD0, the tallest
// trees first, each tree of the previous pass moves one level finer while the budget
// allows. So many trees get some detail before a few get all of it, and no tree is finer
// than a taller one: the tallest are the ones seen from farthest.
void chooseLevels(ForestGltfScene& scene, std::size_t maxTriangles, int coarsest) {
  struct Choice {
    const ForestGltfType* type;
    ForestGltfTree* tree;
  };
  std::vector<Choice> trees;
  std::size_t used = scene.terrain.triangleCount();
  for (ForestGltfType& type : scene.types)
    for (ForestGltfTree& tree : type.trees) {
      trees.push_back({&type, &tree});
      tree.level = coarsest;
      used += type.lods[coarsest].triangleCount();
    }
  requireWithinBudget(scene.terrain.triangleCount(), used, maxTriangles,
                      coarsest == kBillboardLevel);
  std::sort(trees.begin(), trees.end(), [](const Choice& a, const Choice& b) {
    return a.tree->height_m != b.tree->height_m ? a.tree->height_m > b.tree->height_m
                                                : a.tree->id < b.tree->id;
  });
  for (int level = coarsest - 1; level >= 0; --level)
    for (const Choice& c : trees) {
      if (c.tree->level != level + 1) break;  // refined no further in the previous pass
      const std::size_t finer = c.type->lods[level].triangleCount();
      const std::size_t now = c.type->lods[level + 1].triangleCount();
      const std::size_t extra = finer > now ? finer - now : 0;
      if (used + extra > maxTriangles) break;
      used += extra;
      c.tree->level = level;
    }
}

}  // namespace

std::array<glm::ivec2, 2> billboardFrames(int frames) {
  return {impostorFrame({1.0f, 0.0f, 0.0f}, frames), impostorFrame({0.0f, 0.0f, 1.0f}, frames)};
}

TreeMesh billboardMesh(const TreeType& type, int frames) {
  TreeMesh mesh;
  MeshPart& part = mesh.parts.emplace_back();
  part.material = MaterialKind::LeafCluster;  // unused: the billboard has its own material
  const glm::vec3 centre(type.bounds);
  const float r = type.bounds.w;
  const std::array<glm::ivec2, 2> views = billboardFrames(frames);
  for (std::size_t view = 0; view < views.size(); ++view) {
    const glm::vec3 f = frameDirection(views[view], frames);
    glm::vec3 right, up;
    frameAxes(f, right, up);
    // The frame's picture: its top row is up, its left column -right; tile `view` of two.
    const float u0 = 0.5f * static_cast<float>(view), u1 = u0 + 0.5f;
    const auto first = static_cast<std::uint32_t>(part.positions.size());
    part.addVertex(centre - r * right - r * up, f, {u0, 1.0f});
    part.addVertex(centre + r * right - r * up, f, {u1, 1.0f});
    part.addVertex(centre + r * right + r * up, f, {u1, 0.0f});
    part.addVertex(centre - r * right + r * up, f, {u0, 0.0f});
    part.addTriangle(first, first + 1, first + 2);
    part.addTriangle(first, first + 2, first + 3);
  }
  return mesh;
}

namespace {

// How far a type's foliage moves sideways per multiple of its bend bases, relative to its
// height above the stem base (LOD0's foliage centre).
float crownShiftPerBases(const TreeType& type) {
  const FoliageCentre centre = foliageCentre(type.meshes.lods[0]);
  return centre.position.y > 0.0 ? static_cast<float>(centre.bendEast.x / centre.position.y) : 0.0f;
}

// A glTF node cannot bend as the renderer's vertex shader does: the lean becomes a rigid
// tilt of the tree that moves its foliage's centre as far (an instance's scale stretches
// the shift sideways and the height up).
glm::vec2 tiltOf(glm::vec2 lean, float shiftPerBases, float scaleXZ, float scaleY) {
  const float length = glm::length(lean);
  if (length <= 0.0f || shiftPerBases <= 0.0f) return glm::vec2(0.0f);
  return lean / length * std::atan(length * shiftPerBases * scaleXZ / scaleY);
}

}  // namespace

ForestGltfScene forestGltfScene(const Terrain& terrain, const TreeLibrary& library,
                                const Forest& forest, const std::vector<TreeRow>& rows,
                                const ForestGltfOptions& options, const Billboards* billboards) {
  if (rows.size() != forest.size())
    throw InternalError("the forest and its trees' rows differ in length");
  const bool withBillboards = options.billboards || options.lod == kBillboardLevel;
  if (withBillboards &&
      (!billboards || billboards->textures.size() != static_cast<std::size_t>(library.typeCount())))
    throw InternalError("billboards were asked for without their pictures");
  ForestGltfScene scene;
  scene.terrain = terrainPart(terrain);
  for (const Species& s : library.species()) scene.species.push_back(&s);
  const LodSettings switching;
  std::copy(switching.switchPixels.begin(), switching.switchPixels.end(),
            scene.switchPixels.begin());
  scene.screenHeight_px = static_cast<float>(FrameSize{}.height);  // the frames' default
  // The trees of each type, in forest order.
  std::vector<std::vector<std::size_t>> members(library.typeCount());
  for (std::size_t i = 0; i < forest.size(); ++i) members[forest.type[i]].push_back(i);
  for (std::size_t t = 0; t < members.size(); ++t) {
    if (members[t].empty()) continue;
    const TreeType& type = library.type(static_cast<int>(t));
    ForestGltfType& out = scene.types.emplace_back();
    out.name =
        library.species()[type.species].name + "_variant" + std::to_string(type.variant) + "_age" +
        std::to_string(type.ageClass) +
        (library.settings().clearBoleClasses.size() > 1 ? "_crown" + std::to_string(type.crownClass)
                                                        : std::string());
    const float leanShift = crownShiftPerBases(type);
    out.species = type.species;
    const bool everyLevel = options.lod == kAllLods || options.maxTriangles > 0;
    for (int level = 0; level < kLodCount; ++level)
      if (everyLevel || options.lod == level) {
        out.lods[level] = treeMesh(type.meshes.lods[level]);
        if (options.wind)
          for (const WindPart& part : type.meshes.lods[level].parts)
            out.wind[level].push_back(windBases(part));
      }
    if (withBillboards) {
      out.lods[kBillboardLevel] = billboardMesh(type, billboards->settings.frames);
      out.billboardTexture = billboards->textures[t];
    }
    out.trees.reserve(members[t].size());
    for (std::size_t i : members[t]) {
      const TreeRow& row = rows[i];
      out.trees.push_back(
          {.translation = forest.position[i],
           .yaw_rad = forest.yaw[i],
           .tilt_rad = tiltOf(forest.lean[i], leanShift, forest.scaleXZ[i], forest.scaleY[i]),
           .scale = {forest.scaleXZ[i], forest.scaleY[i], forest.scaleXZ[i]},
           .id = row.id,
           .age_years = static_cast<float>(row.age_years),
           .height_m = row.height_m,
           .dbh_m = row.dbh_m,
           .vigor = row.vigor});
    }
  }
  if (options.maxTriangles > 0)
    chooseLevels(scene, options.maxTriangles, withBillboards ? kBillboardLevel : kLodCount - 1);
  return scene;
}

void requireBudgetReachable(const Terrain& terrain, const TreeLibrary& library,
                            const RunFolder& run, int year, const TreeFilter& keep,
                            const ForestGltfOptions& options) {
  if (options.maxTriangles == 0) return;
  // Each type's trees, counted as the rows are read: neither the rows nor a forest held.
  std::vector<std::size_t> treesOfType(static_cast<std::size_t>(library.typeCount()), 0);
  SpeciesNumbering librarySpecies(library, run.dir.string());
  readSnapshotInBatches(
      run, year, keep,
      [&](std::span<const TreeRow> rows, const std::vector<std::string>& speciesNames) {
        const std::vector<int>& species = librarySpecies.of(speciesNames);
        for (const TreeRow& tree : rows)
          ++treesOfType[static_cast<std::size_t>(drawnType(tree, species[tree.species], library))];
      });
  const bool billboards = options.billboards || options.lod == kBillboardLevel;
  std::vector<int> types;
  for (std::size_t t = 0; t < treesOfType.size(); ++t)
    if (treesOfType[t] > 0) types.push_back(static_cast<int>(t));
  library.build(types);  // side by side; the export draws them next
  const std::size_t terrainTriangles = terrainPart(terrain).triangleCount();
  std::size_t used = terrainTriangles;
  for (const int t : types) {
    const TreeType& type = library.type(t);
    const std::size_t each = billboards
                                 ? billboardMesh(type, ImpostorSettings{}.frames).triangleCount()
                                 : type.meshes.lods[kLodCount - 1].triangleCount();
    used += treesOfType[static_cast<std::size_t>(t)] * each;
  }
  requireWithinBudget(terrainTriangles, used, options.maxTriangles, billboards);
}

ForestGltfSummary exportForest(const Terrain& terrain, const TreeLibrary& library,
                               const Forest& forest, const std::vector<TreeRow>& rows,
                               const std::filesystem::path& file, const ForestGltfOptions& options,
                               const Billboards* billboards) {
  return writeForestGltf(forestGltfScene(terrain, library, forest, rows, options, billboards), file,
                         options);
}

}  // namespace eco
