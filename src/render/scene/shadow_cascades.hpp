// Cascaded shadow maps: the ground ahead of the camera is shadowed by a few nested squares,
// each with a depth map of the same size, so that the near field gets fine shadows and the
// far field still gets shadows out to a kilometre and more. The squares grow geometrically
// from the nearest to the farthest (each side ratio^(1/(n-1)) times the last), lie ahead of
// the camera in its horizontal view direction, and are snapped to whole texels of their own
// map so that a moving camera does not make the shadow edges crawl.
#pragma once

#include <array>
#include <cstdint>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "render/scene/camera.hpp"

namespace eco {

inline constexpr int kShadowCascades = 3;

// One shadowed square on the ground plane and the orthographic light view that maps it.
struct ShadowBox {
  glm::vec3 centre{0.0f};
  float halfSize_m = 0.0f;            // 0: no shadow pass
  float mapPixelsPerMetre = 0.0f;     // of the shadow map's orthographic view: sprite sizes
  glm::mat4 lightViewProj{1.0f};      // world -> the map's clip space
  glm::vec3 toSun{0.0f, 1.0f, 0.0f};  // unit, toward the sun the map is seen from
};

using ShadowCascades = std::array<ShadowBox, kShadowCascades>;

struct ShadowReach {
  float near_m = 50.0f;     // half the side of the nearest square
  float range_m = 1200.0f;  // half the side of the farthest: how far ahead shadows reach
};

// The cascades for a camera and a sun direction (unit, toward the sun, above the horizon),
// each with a square depth map of `mapSize` texels.
ShadowCascades shadowCascades(const Camera& camera, glm::vec3 toSun, ShadowReach reach,
                              int mapSize);

// The square of half side `halfSize_m` around `centre` seen from the sun (unit, toward it),
// with a map of `mapSize` texels a side (shadowCascades' boxes, and tests').
ShadowBox shadowBox(glm::vec3 centre, float halfSize_m, glm::vec3 toSun, int mapSize);

// How much of a caster's (a sphere's) shadow a map holds, judged by its disc seen from the
// sun against the map's edge less a texel, the test shadowAt() in shaders/common.glsl
// applies to the points it looks up there (it takes the finest map holding a point):
//   none  the disc lies outside: no point that reads this map lies under the caster;
//   some  the disc reaches inside: cast into this map, so none of its points lacks the shadow
//         of a tree over it (casters are chosen as the points are);
//   all   the disc lies inside: every point the caster can shadow reads this map, so no
//         coarser map need hold it.
enum class MapHolds : std::uint8_t { none, some, all };
MapHolds shadowHeldBy(const ShadowBox& box, glm::vec3 centre, float radius);

}  // namespace eco
