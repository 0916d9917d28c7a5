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

Frustum::Side Frustum::sideOfBox(glm::vec3 lo, glm::vec3 hi, float margin) const {
  bool inside = true;
  for (const glm::vec4& p : planes) {
    const glm::vec3 n(p);
    // The box's corners farthest along the plane's normal and farthest against it.
    const glm::vec3 along(n.x >= 0.0f ? hi.x : lo.x, n.y >= 0.0f ? hi.y : lo.y,
                          n.z >= 0.0f ? hi.z : lo.z);
    const glm::vec3 against(n.x >= 0.0f ? lo.x : hi.x, n.y >= 0.0f ? lo.y : hi.y,
                            n.z >= 0.0f ? lo.z : hi.z);
    if (glm::dot(n, along) + p.w < -margin) return Side::Outside;
    if (glm::dot(n, against) + p.w < margin) inside = false;
  }
  return inside ? Side::Inside : Side::Across;
}

float projectedPixels(float height_m, float distance_m, float pixelsPerRadian) {
  return height_m * pixelsPerRadian / std::max(distance_m, 1e-3f);
}

std::optional<RenderQuality> parseRenderQuality(std::string_view text) {
  for (RenderQuality q : {RenderQuality::Draft, RenderQuality::Balanced, RenderQuality::High})
    if (text == toString(q)) return q;
  return std::nullopt;
}

std::string_view toString(RenderQuality quality) {
  switch (quality) {
    case RenderQuality::Draft:
      return "draft";
    case RenderQuality::Balanced:
      return "balanced";
    case RenderQuality::High:
      return "high";
  }
  return "balanced";
}

std::array<float, 3> switchPixelsFor(RenderQuality quality) {
  // No quality draws the crown hulls (LOD2): measured against LOD0, an impostor magnified
  // up to 3.4 times is nearer the tree than a smooth hull (bench/fidelity_bench).
  switch (quality) {
    // LOD1's leaf clusters are the costliest part of a frame on llvmpipe: draft keeps them
    // for the nearest trees only.
    case RenderQuality::Draft:
      return {1000.0f, 300.0f, 300.0f};
    case RenderQuality::Balanced:
      return {600.0f, 150.0f, 150.0f};
    // LOD0 for every tree taller than 150 pixels, LOD1 down to the impostors at 40: between
    // 40 and 60 pixels LOD1 measured nearer LOD0 than the impostors (bench/fidelity_bench).
    case RenderQuality::High:
      return {150.0f, 40.0f, 40.0f};
  }
  return LodSettings{}.switchPixels;
}

bool tooSmallToDraw(float pixels, const LodSettings& s) {
  return s.forcedLevel < 0 && pixels < s.minPixels;
}

bool mayReachMinPixels(float height_m, float distance_m, float pixelsPerRadian,
                       const LodSettings& s) {
  constexpr float kRoundings = 0.999f;
  return !tooSmallToDraw(projectedPixels(height_m / kRoundings, distance_m, pixelsPerRadian), s);
}

LodChoice chooseLevel(float pixels, const LodSettings& s) {
  if (s.forcedLevel >= 0) return {static_cast<std::int8_t>(s.forcedLevel), -1, 0.0f};
  if (tooSmallToDraw(pixels, s)) return {};
  const int coarsest = s.impostors ? kLevelImpostor : 2;
  int level = 0;
  while (level < coarsest) {
    // The next level drawn: mesh levels whose range below this one is empty are skipped.
    int next = level + 1;
    while (next < coarsest && s.switchPixels[next] >= s.switchPixels[level]) ++next;
    const float upper = s.switchPixels[level] * (1.0f + s.fadeBand);
    const float lower = s.switchPixels[level] * (1.0f - s.fadeBand);
    if (pixels >= upper) return {static_cast<std::int8_t>(level), -1, 0.0f};
    if (pixels > lower) {
      // Linear in pixels across the band: 0 at its top, 1 at its bottom.
      const float fade = (upper - pixels) / (upper - lower);
      return {static_cast<std::int8_t>(level), static_cast<std::int8_t>(next), fade};
    }
    level = next;
  }
  return {static_cast<std::int8_t>(coarsest), -1, 0.0f};
}

}  // namespace eco
