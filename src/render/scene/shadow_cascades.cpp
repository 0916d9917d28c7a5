#include "render/scene/shadow_cascades.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace eco {
namespace {

// Depth of the light's view: the sun looks down on the square from half of it above the
// centre, so terrain and crowns within 2 km above or below the centre cast and receive.
constexpr float kLightDepth_m = 4000.0f;
// The map covers 1.5 times the square's half side: a slanted sun sees the square's
// corners and the crowns standing on it farther out than the square itself.
constexpr float kMapMargin = 1.5f;
// Each square lies ahead of the camera by this share of its half side: it reaches a little
// behind the camera (tall trees there shade the near ground) and mostly ahead.
constexpr float kAhead = 0.7f;

// The up of the sun's view: the vertical, unless the sun stands (nearly) overhead.
glm::vec3 lightUpHint(glm::vec3 toSun) {
  return std::abs(toSun.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(0.0f, 0.0f, -1.0f);
}

}  // namespace

ShadowCascades shadowCascades(const Camera& camera, glm::vec3 toSun, ShadowReach reach,
                              int mapSize) {
  glm::vec3 ahead = camera.forward();
  ahead.y = 0.0f;
  ahead = glm::length(ahead) > 1e-4f ? glm::normalize(ahead) : glm::vec3(0.0f, 0.0f, -1.0f);
  const glm::vec3 upHint = lightUpHint(toSun);
  const glm::vec3 right = glm::normalize(glm::cross(-toSun, upHint));
  const glm::vec3 up = glm::cross(right, -toSun);
  const float nearest = std::min(reach.near_m, reach.range_m);
  const float ratio = reach.range_m / nearest;

  ShadowCascades cascades;
  for (int c = 0; c < kShadowCascades; ++c) {
    const float halfSize = nearest * std::pow(ratio, static_cast<float>(c) / (kShadowCascades - 1));
    const float texel = 2.0f * halfSize * kMapMargin / static_cast<float>(mapSize);
    glm::vec3 centre = camera.position + ahead * (kAhead * halfSize);
    // Whole texels across the sun's view: the map's grid stays put in the world.
    const float x = glm::dot(centre, right), y = glm::dot(centre, up);
    centre +=
        right * (std::round(x / texel) * texel - x) + up * (std::round(y / texel) * texel - y);
    cascades[c] = shadowBox(centre, halfSize, toSun, mapSize);
  }
  return cascades;
}

ShadowBox shadowBox(glm::vec3 centre, float halfSize_m, glm::vec3 toSun, int mapSize) {
  const glm::vec3 upHint = lightUpHint(toSun);
  const float r = halfSize_m * kMapMargin;
  ShadowBox box;
  box.centre = centre;
  box.halfSize_m = halfSize_m;
  box.toSun = toSun;
  box.mapPixelsPerMetre = static_cast<float>(mapSize) / (2.0f * r);
  const glm::mat4 lightView = glm::lookAt(centre + toSun * (0.5f * kLightDepth_m), centre, upHint);
  box.lightViewProj = glm::ortho(-r, r, -r, r, 0.0f, kLightDepth_m) * lightView;
  return box;
}

MapHolds shadowHeldBy(const ShadowBox& box, glm::vec3 centre, float radius) {
  const glm::vec4 p = box.lightViewProj * glm::vec4(centre, 1.0f);  // orthographic: w = 1
  const glm::mat4& m = box.lightViewProj;
  // Across the map -1..1: the centre's farther coordinate, the disc's reach and the edge.
  const float perMetre = glm::length(glm::vec3(m[0][0], m[1][0], m[2][0]));
  const float offset = std::max(std::abs(p.x), std::abs(p.y));
  const float reach = radius * perMetre;
  const float edge = 1.0f - perMetre / box.mapPixelsPerMetre;  // a texel inside
  if (offset - reach >= edge) return MapHolds::none;
  return offset + reach <= edge ? MapHolds::all : MapHolds::some;
}

}  // namespace eco
