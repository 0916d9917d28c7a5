#include "render/scene/culling.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

namespace eco {

Frustum Frustum::fromMatrix(const glm::mat4& m) {
  // Gribb and Hartmann: the planes are sums and differences of the matrix rows.
  auto row = [&](int i) { return glm::vec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
  Frustum f;
  f.planes = {row(3) + row(0), row(3) - row(0), row(3) + row(1),
              row(3) - row(1), row(3) + row(2), row(3) - row(2)};
  for (glm::vec4& p : f.planes) p /= glm::length(glm::vec3(p));
  return f;
}

bool Frustum::intersectsSphere(glm::vec3 centre, float radius) const {
  for (const glm::vec4& p : planes)
    if (glm::dot(glm::vec3(p), centre) + p.w < -radius) return false;
  return true;
}

float projectedPixels(float height_m, float distance_m, float pixelsPerRadian) {
  return height_m * pixelsPerRadian / std::max(distance_m, 1e-3f);
}

LodChoice chooseLevel(float pixels, const LodSettings& s) {
  if (s.forcedLevel >= 0) return {static_cast<std::int8_t>(s.forcedLevel), -1, 0.0f};
  if (pixels < s.minPixels) return {};
  const int coarsest = s.impostors ? kLevelImpostor : 2;
  for (int level = 0; level < 3; ++level) {
    const float upper = s.switchPixels[level] * (1.0f + s.fadeBand);
    const float lower = s.switchPixels[level] * (1.0f - s.fadeBand);
    if (pixels >= upper) return {static_cast<std::int8_t>(level), -1, 0.0f};
    if (pixels > lower && level + 1 <= coarsest) {
      // Linear in pixels across the band: 0 at its top, 1 at its bottom.
      const float fade = (upper - pixels) / (upper - lower);
      return {static_cast<std::int8_t>(level), static_cast<std::int8_t>(level + 1), fade};
    }
    if (level + 1 > coarsest) return {static_cast<std::int8_t>(level), -1, 0.0f};
  }
  return {static_cast<std::int8_t>(coarsest), -1, 0.0f};
}

}  // namespace eco
