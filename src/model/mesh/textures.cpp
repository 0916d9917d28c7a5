#include "model/mesh/textures.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/random.hpp"

namespace eco {
namespace {

float smooth(float t) {
  return t * t * (3.0f - 2.0f * t);
}

float latticeValue(int x, int y, int periodX, int periodY, std::uint64_t seed) {
  x = ((x % periodX) + periodX) % periodX;
  y = ((y % periodY) + periodY) % periodY;
  return static_cast<float>(
             mix64(streamKey(seed, static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y))) >>
             40) /
         static_cast<float>(1 << 24);
}

float valueNoise(float x, float y, int periodX, int periodY, std::uint64_t seed) {
  int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  float fx = smooth(x - static_cast<float>(x0)), fy = smooth(y - static_cast<float>(y0));
  float a = latticeValue(x0, y0, periodX, periodY, seed),
        b = latticeValue(x0 + 1, y0, periodX, periodY, seed);
  float c = latticeValue(x0, y0 + 1, periodX, periodY, seed);
  float d = latticeValue(x0 + 1, y0 + 1, periodX, periodY, seed);
  return (a + (b - a) * fx) + ((c + (d - c) * fx) - (a + (b - a) * fx)) * fy;
}

// Half-width of a broadleaf blade at v (0 petiole .. 1 tip), after Tankard's mirrored
// half-leaf outline: a short petiole, a rounded base and a pointed tip. The tip stops
// short of the edge so mipmaps keep a transparent margin.
float bladeHalfWidth(float v) {
  if (v < 0.06f) return 0.025f;
  float t = (v - 0.06f) / 0.90f;
  if (t >= 1.0f) return 0.0f;
  return 0.47f * std::pow(std::sin(std::numbers::pi_v<float> * std::pow(t, 0.75f)), 0.85f);
}

// Inside a broadleaf blade lying along v (0 petiole .. 1 tip), centred at u = 0.5.
bool insideBlade(float u, float v) {
  return v >= 0.0f && v <= 1.0f && std::abs(u - 0.5f) < bladeHalfWidth(v);
}

// Coverage of one needle lying along v at u = 0.5, with a sharp tip.
bool insideNeedle(float u, float v, float halfWidth) {
  if (v < 0.0f || v > 1.0f) return false;
  return std::abs(u - 0.5f) < halfWidth * (1.0f - std::pow(v, 6.0f));
}

// A kTextureSize square texture with colorAt(u, v) at every pixel centre (u to the right,
// v down, both in [0, 1]).
template <typename ColorAt>
Image paint(ColorAt colorAt) {
  Image image(kTextureSize, kTextureSize);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      image.set(x, y, colorAt((x + 0.5f) / image.width, (y + 0.5f) / image.height));
  return image;
}

glm::vec4 leafColorAt(const Appearance& look, float u, float v) {
  float n = tileableNoise(u, v, 8, 3, 7);
  glm::vec3 c = look.leafColor * (0.8f + 0.4f * n);
  float fromMidrib = std::abs(u - 0.5f);
  if (fromMidrib < 0.015f) c = glm::mix(c, glm::vec3(0.75f, 0.85f, 0.45f), 0.5f);  // midrib
  float vein = std::fmod(v * 9.0f - fromMidrib * 6.0f + 10.0f, 1.0f);
  if (vein < 0.07f) c *= 1.15f;  // lateral veins, running toward the tip
  return glm::vec4(c, 1.0f);
}

}  // namespace

float tileableNoise(float x, float y, int baseFrequency, int octaves, std::uint64_t seed) {
  return tileableNoise(x, y, baseFrequency, baseFrequency, octaves, seed);
}

float tileableNoise(float x, float y, int frequencyX, int frequencyY, int octaves,
                    std::uint64_t seed) {
  float sum = 0.0f, amplitude = 0.5f, total = 0.0f;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * valueNoise(x * frequencyX, y * frequencyY, frequencyX, frequencyY, seed + o);
    total += amplitude;
    amplitude *= 0.5f;
    frequencyX *= 2;
    frequencyY *= 2;
  }
  return sum / total;
}

Image makeBarkTexture(const Appearance& look) {
  const auto roughness = static_cast<float>(look.barkRoughness);
  return paint([&](float u, float v) {
    // Fissures follow an iso-line of noise stretched along the stem (v), so they run
    // lengthwise and enclose plates; rough bark has wide, dark fissures.
    float plates = tileableNoise(u, v, 6, 2, 4, 11);
    float toFissure = std::abs(2.0f * plates - 1.0f);
    float fissure =
        roughness * (1.0f - std::clamp(toFissure / (0.04f + 0.14f * roughness), 0.0f, 1.0f));
    float grain = tileableNoise(u, v, 16, 3, 12);
    float plateShade = 0.85f + 0.3f * tileableNoise(u, v, 3, 2, 13);
    glm::vec3 c = look.barkColor * plateShade * (0.85f + 0.3f * grain) * (1.0f - 0.75f * fissure);
    return glm::vec4(c, 1.0f);
  });
}

Image makeLeafTexture(const Appearance& look) {
  return paint([&](float u, float v) {
    bool inside = false;
    if (look.leafShape == LeafShape::Broadleaf) {
      inside = insideBlade(u, v);
    } else {  // a tuft of needles fanning out from the base
      for (int k = 0; k < 13 && !inside; ++k) {
        float angle = (static_cast<float>(k) / 12.0f - 0.5f) * 0.9f;
        float along = v * std::cos(angle) + (u - 0.5f) * std::sin(angle);
        float aside = -v * std::sin(angle) + (u - 0.5f) * std::cos(angle);
        inside = along < 0.98f && insideNeedle(aside + 0.5f, along, 0.012f);
      }
    }
    return inside ? leafColorAt(look, u, v) : glm::vec4(look.leafColor, 0.0f);
  });
}

Image makeNeedleTexture(const Appearance& look) {
  return paint([&](float u, float v) {
    glm::vec3 c = look.leafColor * (0.85f + 0.3f * (1.0f - std::abs(u - 0.5f) * 2.0f));
    return glm::vec4(c, insideNeedle(u, v, 0.4f) ? 1.0f : 0.0f);
  });
}

Image makeNeedleClusterTexture(const Appearance& look) {
  // Needles stamped at fixed pseudo-random places; kNeedleClusterCoverage records how much
  // of the card they cover.
  struct Stamp {
    float cx, cy, angle, size;
  };
  std::vector<Stamp> stamps;
  Rng rng(streamKey(purpose("leaf-cluster-texture")));
  // Spread over the whole card (keeping the stamps inside it) so that clusters read as
  // foliage rather than as a blob in the middle of a square.
  for (int i = 0; i < 70; ++i) {
    float size = static_cast<float>(rng.uniform(0.25, 0.4));
    float margin = 0.5f * size;
    stamps.push_back({static_cast<float>(rng.uniform(margin, 1.0 - margin)),
                      static_cast<float>(rng.uniform(margin, 1.0 - margin)),
                      static_cast<float>(rng.uniform(0.0, 2.0 * std::numbers::pi)), size});
  }
  return paint([&](float px, float py) {
    glm::vec4 c(look.leafColor, 0.0f);
    for (const Stamp& s : stamps) {
      // Into the stamp's leaf coordinates: v along the blade, u across it.
      float dx = px - s.cx, dy = py - s.cy;
      float v = (dx * std::cos(s.angle) + dy * std::sin(s.angle)) / s.size + 0.5f;
      float u = (-dx * std::sin(s.angle) + dy * std::cos(s.angle)) / s.size + 0.5f;
      if (insideNeedle(u, v, 0.03f))
        c = leafColorAt(look, u, v) * glm::vec4(glm::vec3(0.75f + s.size), 1.0f);
    }
    return c;
  });
}

Material makeMaterial(MaterialKind kind, const Species& species) {
  const Appearance& look = species.appearance;
  Material m;
  m.kind = kind;
  m.name = species.name + "_" + toString(kind);
  switch (kind) {
    case MaterialKind::Bark:
      m.texture = makeBarkTexture(look);
      m.repeat = true;
      break;
    case MaterialKind::Leaf:
      m.texture = makeLeafTexture(look);
      m.alphaMask = m.doubleSided = true;
      m.roughness = 0.7f;
      break;
    case MaterialKind::Needle:
      m.texture = makeNeedleTexture(look);
      m.alphaMask = m.doubleSided = true;
      m.roughness = 0.7f;
      break;
    case MaterialKind::LeafCluster:
      m.texture = makeNeedleClusterTexture(look);  // only conifers' LOD1 has clusters
      m.alphaMask = m.doubleSided = true;
      m.roughness = 0.7f;
      break;
    case MaterialKind::Crown:  // opaque, the mean colour of a leaf
      m.baseColor = glm::vec4(look.leafColor * 0.85f, 1.0f);
      break;
  }
  return m;
}

}  // namespace eco
