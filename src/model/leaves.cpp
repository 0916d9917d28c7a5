#include "model/leaves.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "core/rotation.hpp"

namespace eco {
namespace {

struct Placement {
  double along = 1.0;
  double azimuth_deg = 0.0;
  double elevation_deg = 45.0;
};

Placement placementFor(LeafDistribution distribution, int count, int i, double phyllotaxis_deg) {
  const int n = count;
  switch (distribution) {
    case LeafDistribution::Spiral:  // one leaf per node, azimuth advancing by the phyllotaxis
      return {(i + 1.0) / n, i * phyllotaxis_deg, 55.0};
    case LeafDistribution::Stacked: {  // opposite pairs, each pair turned 90 degrees (decussate)
      int pair = i / 2;
      int pairs = (n + 1) / 2;
      return {(pair + 1.0) / pairs, pair * 90.0 + (i % 2) * 180.0, 70.0};
    }
    case LeafDistribution::Staggered:  // alternating left and right in one plane (distichous)
      return {(i + 1.0) / n, (i % 2) * 180.0, 60.0};
    case LeafDistribution::Bunched:  // a rosette at the tip
      return {1.0, i * 360.0 / n, 35.0};
    case LeafDistribution::Coniferous:  // needles all round the shoot along its length
      return {(i + 0.5) / n, i * 137.508, 40.0};
  }
  return {};
}

// cos and sin of a small angle (|x| < 0.15 rad) by Taylor series; error below 1e-9.
void smallSinCos(float x, float& c, float& s) {
  float x2 = x * x;
  c = 1.0f - x2 * (0.5f - x2 * (1.0f / 24.0f));
  s = x * (1.0f - x2 * (1.0f / 6.0f - x2 * (1.0f / 120.0f)));
}

constexpr float kAzimuthJitter_rad = radians(8.0f);
constexpr float kElevationJitter_rad = radians(6.0f);

}  // namespace

LeafPattern makeLeafPattern(LeafDistribution distribution, int count, double phyllotaxis_deg) {
  LeafPattern pattern;
  pattern.distribution = distribution;
  for (int i = 0; i < count; ++i) {
    Placement p = placementFor(distribution, count, i, phyllotaxis_deg);
    LeafPattern::Slot slot;
    slot.along = static_cast<float>(p.along);
    slot.cosAzimuth = static_cast<float>(std::cos(radians(p.azimuth_deg)));
    slot.sinAzimuth = static_cast<float>(std::sin(radians(p.azimuth_deg)));
    slot.cosElevation = static_cast<float>(std::cos(radians(p.elevation_deg)));
    slot.sinElevation = static_cast<float>(std::sin(radians(p.elevation_deg)));
    pattern.slots.push_back(slot);
  }
  return pattern;
}

void placeLeaves(const BranchSegment& twig, std::int32_t twigIndex, const LeafPattern& pattern,
                 float size_m, Rng& rng, std::vector<Leaf>& out) {
  const glm::vec3 axis = twig.frame[1];
  const glm::vec3 side = twig.frame[0];
  const glm::vec3 front = twig.frame[2];
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const LeafKind kind =
      pattern.distribution == LeafDistribution::Coniferous ? LeafKind::Needle : LeafKind::Card;
  for (const LeafPattern::Slot& slot : pattern.slots) {
    // Turn the slot's azimuth and elevation by the jitter: cos(a + d) = cos a cos d - sin a sin d.
    float cd, sd, ce, se;
    smallSinCos(kAzimuthJitter_rad * static_cast<float>(rng.uniform(-1.0, 1.0)), cd, sd);
    smallSinCos(kElevationJitter_rad * static_cast<float>(rng.uniform(-1.0, 1.0)), ce, se);
    float cosAzimuth = slot.cosAzimuth * cd - slot.sinAzimuth * sd;
    float sinAzimuth = slot.sinAzimuth * cd + slot.cosAzimuth * sd;
    float cosElevation = slot.cosElevation * ce - slot.sinElevation * se;
    float sinElevation = slot.sinElevation * ce + slot.cosElevation * se;
    glm::vec3 outward = cosAzimuth * side + sinAzimuth * front;
    Leaf leaf;
    leaf.position = twig.start + axis * (twig.length_m * slot.along);
    // axis and outward are orthonormal, so the blade direction is a unit vector.
    leaf.direction = cosElevation * axis + sinElevation * outward;
    // Blades turn their face to the sky: the normal is "up" made perpendicular to the blade.
    glm::vec3 normal = up - glm::dot(up, leaf.direction) * leaf.direction;
    if (glm::dot(normal, normal) < 1e-6f) normal = glm::cross(leaf.direction, side);
    leaf.normal = glm::normalize(normal);
    leaf.size_m = size_m;
    leaf.segment = twigIndex;
    leaf.kind = kind;
    out.push_back(leaf);
  }
}

}  // namespace eco
