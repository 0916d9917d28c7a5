// The ground: the terrain's triangles and normals (sim/terrain_mesh.hpp), coloured by
// altitude and slope in the shader, or by a condition map as an overlay.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "render/gl/gl_objects.hpp"
#include "render/gl/shader.hpp"
#include "render/scene/culling.hpp"
#include "render/scene/forest_floor.hpp"
#include "sim/grid.hpp"
#include "sim/terrain.hpp"

namespace eco {

class TerrainRenderer {
 public:
  explicit TerrainRenderer(const Terrain& terrain);

  // Colours the ground by a field on its colour ramp (condition_maps.hpp), stretched over
  // the field's range; `name` picks the ramp.
  void setOverlay(const std::string& name, const Field& values);
  void clearOverlay() { overlay_ = GlName(); }
  // The share of each cell under crowns (forest_floor.hpp): leaf litter and moss there,
  // grass in the open. Without it the ground is open everywhere.
  void setCanopyCover(const Field& cover);
  // The crowns of each cell by the trees' heights and their colour (forest_floor.hpp): the
  // ground shows the crowns of the trees too small to draw at its distance (draw()'s
  // `unresolvedPerMetre`). Without it the ground shows none.
  void setCanopyFloor(const CanopyFloor& floor);
  // The ground's moisture (Ellenberg F, sim's moistureOf): dry meadows brown toward straw,
  // wet ones are lusher. Without it the ground is fresh (F 5) everywhere.
  void setMoisture(const Field& moisture);
  bool hasOverlay() const { return static_cast<bool>(overlay_); }

  // Draws the chunks in the frustum; returns the triangles drawn. A tree shorter than
  // `unresolvedPerMetre` times its distance is not drawn (smaller than LodSettings's
  // minPixels): the ground there shows its crown (setCanopyFloor). 0: none.
  std::size_t draw(const Frustum& frustum, bool shadowPass, float unresolvedPerMetre = 0.0f) const;
  std::size_t triangleCount() const { return indexCount_ / 3; }

  static constexpr int kChunkCells = 32;  // grid squares per chunk side

 private:
  Grid grid_;
  float lowest_m_ = 0.0f, highest_m_ = 0.0f;
  Program program_, shadowProgram_;
  GlName vertices_, indices_, vertexArray_, overlay_, canopyCover_, moisture_;
  // kCanopyHeightTops_m's first four and last four running sums of crowns, and their colour.
  GlName crownsBelowLow_, crownsBelowHigh_, crownColor_;
  GLsizei indexCount_ = 0;
  struct Chunk {
    std::size_t firstIndex = 0;
    GLsizei indexCount = 0;
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
  };
  std::vector<Chunk> chunks_;
  // Scratch of draw(): the visible chunks' index counts and offsets.
  mutable std::vector<GLsizei> counts_;
  mutable std::vector<const void*> offsets_;
};

}  // namespace eco
