#include "model/leaves.hpp"

#include <cmath>

#include "model/rotation.hpp"

namespace eco {
namespace {

struct LeafPlacement {
  double along = 1.0;        // 0 at the twig's base, 1 at its tip
  double azimuth_deg = 0.0;  // around the twig, from the twig frame's x axis
  double elevation_deg = 45.0;  // angle between blade and twig axis
};

LeafPlacement placementFor(const LeafLayout& layout, int i) {
  const int n = layout.count;
  switch (layout.distribution) {
    case LeafDistribution::Spiral:  // one leaf per node, azimuth advancing by the phyllotaxis
      return {(i + 1.0) / n, i * layout.phyllotaxis_deg, 55.0};
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

}  // namespace

void placeLeaves(const BranchSegment& twig, std::int32_t twigIndex, const LeafLayout& layout,
                 Rng& rng, std::vector<Leaf>& out) {
  const glm::vec3 axis = twig.frame[1];
  const glm::vec3 side = twig.frame[0];
  const glm::vec3 front = twig.frame[2];
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  for (int i = 0; i < layout.count; ++i) {
    LeafPlacement p = placementFor(layout, i);
    // Small natural irregularity; never changes which distribution it is.
    double azimuth = radians(p.azimuth_deg + rng.uniform(-8.0, 8.0));
    double elevation = radians(p.elevation_deg + rng.uniform(-6.0, 6.0));
    glm::vec3 outward = static_cast<float>(std::cos(azimuth)) * side +
                        static_cast<float>(std::sin(azimuth)) * front;
    Leaf leaf;
    leaf.position = twig.start + axis * (twig.length_m * static_cast<float>(p.along));
    leaf.direction = glm::normalize(static_cast<float>(std::cos(elevation)) * axis +
                                    static_cast<float>(std::sin(elevation)) * outward);
    // Blades turn their face to the sky: the normal is "up" made perpendicular to the blade.
    glm::vec3 normal = up - glm::dot(up, leaf.direction) * leaf.direction;
    if (glm::dot(normal, normal) < 1e-6f) normal = glm::cross(leaf.direction, side);
    leaf.normal = glm::normalize(normal);
    leaf.size_m = layout.size_m;
    leaf.segment = twigIndex;
    leaf.kind = layout.distribution == LeafDistribution::Coniferous ? LeafKind::Needle : LeafKind::Card;
    out.push_back(leaf);
  }
}

}  // namespace eco
