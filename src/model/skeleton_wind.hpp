// EcoMod's wind (Zamuda et al., section II; docs/model.md) applied to a skeleton another
// generator built at rest, so L-system trees sway and lean like strand trees:
//   undirected: every branch turns about its parent's x and z axes by
//     alpha_x(t) = sin(t + R_x) w_s (1 - k_f) l_0   (likewise alpha_z with R_z),
//     l_0 the parent segment's length, R_x and R_z phases per branch node from the seed;
//   directed: every branch turns toward the wind by alpha_w = (S_0 / S) w_g, S_0 the tips
//     above its parent and S those of the tree.
// Rotations accumulate from the root as in the strand model; each segment keeps its length
// and stays attached where it was, and leaves move with their segment.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "model/skeleton.hpp"

namespace eco {

struct SkeletonWind {
  double directed_wg = 0.0;             // degrees at S_0 = S
  double undirected_ws = 0.0;           // degrees per metre of parent branch
  glm::dvec3 direction{0.0, 1.0, 0.0};  // toward which the wind blows
  double flexibility = 1.0;             // k_f: sway scales with 1 - k_f
  double time = 0.0;                    // t, radians
  std::uint64_t seed = 1;               // the phases R_x, R_z
  bool calm() const { return directed_wg == 0.0 && (undirected_ws == 0.0 || flexibility >= 1.0); }
};

// Does nothing in a calm (the skeleton stays bit-identical).
void applyWind(TreeSkeleton& skeleton, const SkeletonWind& wind);

}  // namespace eco
