// Hemi-octahedral impostors (an octahedral impostor over the upper hemisphere; Tankard's
// billboards, 000_...txt section 3.5, taken to many directions). Each species and age class
// is rendered from frames x frames directions spread over the hemisphere by the
// hemi-octahedral map into an atlas of albedo and normal tiles; a far tree is a point sprite
// showing the frames around the direction it is seen from, lit per pixel from the baked
// normals, so it agrees with the mesh under any sun. hemiOctEncode exists in
// shaders/common.glsl too.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/scene/culling.hpp"

namespace eco {

struct Species;

struct ImpostorSettings {
  int frames = 8;       // per side of the atlas: frames^2 directions
  int tilePixels = 64;  // per frame
  int bakeLod = 1;  // the mesh the frames show (LOD1: the look of LOD0 at a fraction of the cost)
  // Blend the three frames around the seen direction (barycentric over the frame grid), so
  // the picture turns smoothly with the view instead of jumping from frame to frame; false:
  // the nearest frame alone.
  bool blendFrames = true;
  // Draw each sprite only as large as its frames' content reaches (frameExtents) instead of
  // the bounding sphere's square: the same picture from fewer fragments. False: the square.
  bool cropSprites = true;
  // A folder where baked atlases are kept between runs (core/disk_cache.hpp), under a key
  // of everything they are made from; empty: baked by every renderer.
  std::filesystem::path cacheFolder{};
};

// High quality bakes its frames from LOD0: far trees look like the full model (the 300 m
// view's SSIM against LOD0 rises from 0.83 to 0.87) for about four times the baking time;
// the others bake LOD1, but a species that bears needles LOD0 (impostorBakeLevel).
// Draft and balanced (view, where the camera moves and impostors stand
// for trees up to 220-300 pixels tall) blend frames; high, whose impostors are under 60
// pixels, shows the nearest: blending softened its LOD0 frames' fine branches and measured
// further from the full model in still pictures (docs/rendering.md, "Impostors").
ImpostorSettings impostorSettingsFor(RenderQuality quality);

// The mesh level a species' impostor frames show: the quality's `bakeLod`, but LOD0 for a
// species that bears needles, whose LOD1 gathers them into cluster cards: baked from those,
// a far pine neither covers nor colours its pixels as its needles do (docs/rendering.md,
// "Impostors").
int impostorBakeLevel(const Species& species, int bakeLod);

// Unit direction with y >= 0 -> [0, 1]^2, and back.
glm::vec2 hemiOctEncode(glm::vec3 direction);
glm::vec3 hemiOctDecode(glm::vec2 uv);
// The frame (column, row) that shows a tree seen from `direction` (tree frame), and the
// direction that frame was baked from.
glm::ivec2 impostorFrame(glm::vec3 direction, int frames);
glm::vec3 frameDirection(glm::ivec2 frame, int frames);
// The right and up axes of the orthographic camera that bakes the frame of direction f.
void frameAxes(glm::vec3 f, glm::vec3& right, glm::vec3& up);

// How far each frame's tree reaches from the frame's centre: the largest of |x| and |y|
// over its covered texels (alpha above 0, each texel's far corner), in units of the
// frame's half side (0..1), frames in rows (column + row * frames). `alpha` is the atlas's
// coverage, frames x tile texels a side, rows as OpenGL reads them. A sprite need cover
// no more than this square: the bounding sphere's square it was drawn as holds mostly
// empty texels, which cost a fragment each (seen from a high sun, a crown's disc fills a
// tenth of it).
std::vector<float> frameExtents(std::span<const std::uint8_t> alpha, int frames, int tile);

}  // namespace eco
