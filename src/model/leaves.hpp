// Leaf placement on a terminal segment (S_0 = 1) for EcoMod's five leaf distributions
// (Zamuda et al., section II.A). The paper only names them; docs/model.md defines each.
#pragma once

#include <cstdint>
#include <vector>

#include "core/random.hpp"
#include "model/skeleton.hpp"
#include "model/species.hpp"

namespace eco {

struct LeafLayout {
  LeafDistribution distribution = LeafDistribution::Spiral;
  int count = 0;        // leaves on this twig
  float size_m = 0.0f;  // blade length
  double phyllotaxis_deg = 137.508;  // azimuth step of the spiral
};

void placeLeaves(const BranchSegment& twig, std::int32_t twigIndex, const LeafLayout& layout,
                 Rng& rng, std::vector<Leaf>& out);

}  // namespace eco
