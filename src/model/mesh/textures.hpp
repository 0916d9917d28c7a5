// Procedural textures and the materials that use them. Nothing is downloaded: bark, leaf,
// needle and leaf-cluster images are generated from the species' colours with tileable
// value noise.
#pragma once

#include <optional>
#include <string>

#include <glm/vec4.hpp>

#include "core/image.hpp"
#include "model/mesh/mesh.hpp"
#include "model/species.hpp"

namespace eco {

inline constexpr int kTextureSize = 256;

// Fraction of each card texture that is opaque (alpha >= 0.5). LOD1 sizes its needle
// clusters with these so that the visible needle area stays the same; the texture tests
// check them against the generated images.
inline constexpr float kBroadleafCoverage = 0.58f;
inline constexpr float kNeedleTuftCoverage = 0.22f;
inline constexpr float kNeedleCoverage = 0.69f;
inline constexpr float kNeedleClusterCoverage = 0.29f;

Image makeBarkTexture(const Appearance& look);
Image makeLeafTexture(const Appearance& look);    // broadleaf or needle tuft; v = 0 at the petiole
Image makeNeedleTexture(const Appearance& look);  // one needle along the card
Image makeNeedleClusterTexture(const Appearance& look);

// Tileable fractal value noise in [0, 1]; x and y in texture units (periodic with period 1).
float tileableNoise(float x, float y, int baseFrequency, int octaves, std::uint64_t seed);
// The same with its own frequency along each axis (stretched features, still tileable).
float tileableNoise(float x, float y, int frequencyX, int frequencyY, int octaves,
                    std::uint64_t seed);

struct Material {
  MaterialKind kind = MaterialKind::Bark;
  std::string name;
  glm::vec4 baseColor{1.0f};  // multiplies the texture; the whole colour when there is none
  std::optional<Image> texture;
  bool alphaMask = false;  // cut out where texture alpha < 0.5
  bool doubleSided = false;
  bool repeat = false;  // texture wraps (bark) or clamps (cards)
  float roughness = 0.9f;
};

Material makeMaterial(MaterialKind kind, const Species& species);

}  // namespace eco
