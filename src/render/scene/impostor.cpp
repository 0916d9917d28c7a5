#include "render/scene/impostor.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/error.hpp"
#include "model/mesh/lod.hpp"

namespace eco {

glm::vec2 hemiOctEncode(glm::vec3 d) {
  d /= std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  return glm::vec2(d.x + d.z, d.x - d.z) * 0.5f + 0.5f;
}

glm::vec3 hemiOctDecode(glm::vec2 uv) {
  const glm::vec2 e = uv * 2.0f - 1.0f;
  glm::vec3 d((e.x + e.y) * 0.5f, 0.0f, (e.x - e.y) * 0.5f);
  d.y = 1.0f - std::abs(d.x) - std::abs(d.z);
  return glm::normalize(d);
}

glm::ivec2 impostorFrame(glm::vec3 direction, int frames) {
  direction.y = std::max(direction.y, 0.0f);
  const glm::vec2 cell = glm::floor(hemiOctEncode(direction) * static_cast<float>(frames));
  return glm::clamp(glm::ivec2(cell), glm::ivec2(0), glm::ivec2(frames - 1));
}

glm::vec3 frameDirection(glm::ivec2 frame, int frames) {
  return hemiOctDecode((glm::vec2(frame) + 0.5f) / static_cast<float>(frames));
}

void frameAxes(glm::vec3 f, glm::vec3& right, glm::vec3& up) {
  const glm::vec3 reference = std::abs(f.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, -1);
  right = glm::normalize(glm::cross(reference, f));
  up = glm::cross(f, right);
}

std::vector<float> frameExtents(std::span<const std::uint8_t> alpha, int frames, int tile) {
  const auto side = static_cast<std::size_t>(frames) * tile;
  ECO_ASSERT(alpha.size() == side * side, "alpha=" << alpha.size() << " side=" << side);
  std::vector<float> extents(static_cast<std::size_t>(frames) * frames, 0.0f);
  const float half = 0.5f * static_cast<float>(tile);
  for (std::size_t y = 0; y < side; ++y)
    for (std::size_t x = 0; x < side; ++x) {
      if (alpha[y * side + x] == 0) continue;
      const int column = static_cast<int>(x) / tile, row = static_cast<int>(y) / tile;
      // The texel's corner farthest from the frame's centre, in texels.
      const float tx = static_cast<float>(static_cast<int>(x) % tile);
      const float ty = static_cast<float>(static_cast<int>(y) % tile);
      const float reach = std::max(std::max(std::abs(tx - half), std::abs(tx + 1.0f - half)),
                                   std::max(std::abs(ty - half), std::abs(ty + 1.0f - half)));
      float& extent = extents[static_cast<std::size_t>(row) * frames + column];
      extent = std::max(extent, reach / half);
    }
  return extents;
}

int impostorBakeLevel(const Species& species, int bakeLod) {
  return bearsNeedles(species) ? 0 : bakeLod;
}

ImpostorSettings impostorSettingsFor(RenderQuality quality) {
  ImpostorSettings settings;
  settings.bakeLod = quality == RenderQuality::High ? 0 : 1;
  settings.blendFrames = quality != RenderQuality::High;
  return settings;
}

}  // namespace eco
