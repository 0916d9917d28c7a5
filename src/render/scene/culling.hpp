// Per-frame choices made on the CPU for every tree: is it in the view frustum, and which
// level of detail draws it. LOD follows the tree's projected height in pixels; near each
// switching size the two levels cross-fade over a band (screen-door dithering with
// complementary masks), so nothing pops and no per-tree state is needed: a frame depends
// only on the camera, which keeps stills and time-lapse frames reproducible.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace eco {

// Levels drawn by the renderer: the model's three meshes, then the impostor.
inline constexpr int kLevelImpostor = 3;
inline constexpr int kLevelCount = 4;

struct Frustum {
  std::array<glm::vec4, 6> planes;  // inward normals: inside where dot(n, p) + d >= 0

  static Frustum fromMatrix(const glm::mat4& viewProjection);
  bool intersectsSphere(glm::vec3 centre, float radius) const;
  // Where an axis-aligned box lies: wholly beyond one plane (every sphere inside it fails
  // intersectsSphere), wholly within all six (every sphere centred in it passes), or across;
  // a box within `margin` metres of a plane counts as across.
  enum class Side { Outside, Inside, Across };
  Side sideOfBox(glm::vec3 lo, glm::vec3 hi, float margin) const;
};

struct LodSettings {
  // Projected tree height (pixels) above which each level is used: LOD0, LOD1, LOD2;
  // smaller trees are impostors, and trees under minPixels are not drawn. A mesh level whose
  // size is not below the finer one's is skipped (high quality skips LOD2). Impostor frames
  // are 64 pixels (ImpostorSettings). The defaults use every level (the glTF export's
  // screen coverages); the qualities below skip the crown hulls.
  std::array<float, 3> switchPixels{600.0f, 220.0f, 100.0f};
  float minPixels = 1.0f;
  float fadeBand = 0.15f;  // cross-fade over switch * (1 +- fadeBand)
  bool impostors = true;   // false: LOD2 all the way out
  int forcedLevel = -1;    // >= 0: every tree at this level, no fading (tests, benchmark)
};

struct LodChoice {
  std::int8_t level = -1;   // -1: not drawn
  std::int8_t fadeTo = -1;  // the coarser level it fades into, or -1
  float fade = 0.0f;        // share of the pixels the coarser level takes, 0..1
};

// How much of the forest is drawn at full detail: the switching sizes of each quality,
// chosen by measurement (docs/rendering.md, "Quality levels").
enum class RenderQuality { Draft, Balanced, High };
// "draft", "balanced" or "high"; nullopt for anything else.
std::optional<RenderQuality> parseRenderQuality(std::string_view text);
std::string_view toString(RenderQuality quality);
std::array<float, 3> switchPixelsFor(RenderQuality quality);

// Height in pixels of an object of height `height_m` at `distance_m` (perspective).
float projectedPixels(float height_m, float distance_m, float pixelsPerRadian);
LodChoice chooseLevel(float pixels, const LodSettings& settings);
// Whether a tree of `pixels` is neither drawn nor casts a shadow: under minPixels, where no
// level is forced on every tree.
bool tooSmallToDraw(float pixels, const LodSettings& settings);
// Whether a tree `height_m` tall (its type's height times its vertical scale) at
// `distance_m` may be drawn or cast a shadow: not tooSmallToDraw, with a thousandth of room
// for the roundings of the renderer's own sums of each tree's distance. A test that drops the
// trees for which it is false before the renderer sees them (ForestIndex's bands, a still's
// trees) changes nothing the renderer draws.
bool mayReachMinPixels(float height_m, float distance_m, float pixelsPerRadian,
                       const LodSettings& settings);

}  // namespace eco
