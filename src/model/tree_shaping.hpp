// A tree shaped by where it stands (docs/model.md, "Shaped by the site"). EcoMod's abstract:
// "our obtained procedural models can also be shaped by placing them in natural
// environments". The site reaches the model through handles the model already has:
//   light:     the directed vector gains a horizontal part toward where the light comes from
//              (phototropism), kPhototropism_wg for light from one side only, in proportion
//              to how one-sided the light is;
//   wind:      likewise downwind, kWindLean_wg on the most exposed sites (a steady directed
//              wind: a lean, branches flagged downwind);
//   crowding:  side branches of the stem below the crown base are pruned (self-pruning), so a
//              tree grown in a dense stand has a clear bole under a short crown.
// Algorithm 1 turns every branch toward the directed vector by alpha_w = (S_0 / S) w_g
// degrees: the stem, which carries most strands, follows it most. A monopodial pine, whose
// stem carries its strands high up, leans far more than a sympodial beech, whose strands
// part low (ecologically apt: beech answers a gap mainly with its crown's plasticity).
// In even light, calm air and the open (a neutral site) the tree is the species' own, bit
// for bit.
#pragma once

#include <glm/vec2.hpp>

#include "model/skeleton.hpp"

namespace eco {

// In degrees of alpha_w at the stem base, as the paper's w_g (0..10); ours, chosen so that
// a pine at a forest edge leans about 15 degrees and one on the most exposed ridge about 20.
inline constexpr double kPhototropism_wg = 3.0;  // light from one side only
inline constexpr double kWindLean_wg = 3.0;      // the most exposed site

struct SiteShaping {
  // Toward the light, horizontal (east, south); its length is how one-sided the light is,
  // 0 (even all round) to 1 (from one direction only).
  glm::dvec2 light{0.0};
  // Toward where the prevailing wind blows (east, south); its length is the site's exposure,
  // 0 (sheltered, or open level ground) to 1 (the most exposed).
  glm::dvec2 wind{0.0};
  // The share of the tree's height below its crown base, with its side branches pruned.
  double clearBole = 0.0;
  bool neutral() const {
    return light == glm::dvec2(0.0) && wind == glm::dvec2(0.0) && clearBole <= 0.0;
  }
};

// The horizontal directed vector (east, south; w_g units) a site adds to the species' own.
glm::dvec2 shapingLean(const SiteShaping& site);

// Removes the stem's side branches (with everything they carry) that start below `share` of
// the stem's length, measured along the stem from its base. The stem is the chain of
// segments from the base that each continue their parent; distances along it do not change
// with the wind, so every pose of a tree loses the same branches.
void pruneClearBole(TreeSkeleton& skeleton, double share);

}  // namespace eco
