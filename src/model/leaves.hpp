// Leaf placement on a terminal segment (S_0 = 1) for EcoMod's five leaf distributions
// (Zamuda et al., section II.A). The paper only names them; docs/model.md defines each.
#pragma once

#include <cstdint>
#include <vector>

#include "core/random.hpp"
#include "model/skeleton.hpp"
#include "model/species.hpp"

namespace eco {

// Where leaf i of `count` sits on a twig, before individual jitter. It depends only on the
// distribution and the count, so one pattern (with its trigonometry done) serves every
// twig of a tree: a pine places 180000 leaves.
struct LeafPattern {
  struct Slot {
    float along = 1.0f;                              // 0 at the twig's base, 1 at its tip
    float cosAzimuth = 1.0f, sinAzimuth = 0.0f;      // around the twig, from its frame's x
    float cosElevation = 1.0f, sinElevation = 0.0f;  // blade against the twig axis
  };
  LeafDistribution distribution = LeafDistribution::Spiral;
  std::vector<Slot> slots;
};

LeafPattern makeLeafPattern(LeafDistribution distribution, int count,
                            double phyllotaxis_deg = 137.508);

// Appends one leaf per slot of the pattern, each with a small random turn (at most 8
// degrees in azimuth, 6 in elevation) so that no two twigs look alike.
void placeLeaves(const BranchSegment& twig, std::int32_t twigIndex, const LeafPattern& pattern,
                 float size_m, Rng& rng, std::vector<Leaf>& out);

}  // namespace eco
