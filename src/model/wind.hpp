// EcoMod's wind (Zamuda et al., section II, Algorithm 1; docs/model.md), in one place for
// every generator. A generator builds its skeleton's structure and joints at rest; the wind
// then poses it:
//   undirected: every branch turns about its frame's x and z axes (after its twist) by
//     alpha_x(t) = sin(t + R_x) w_s (1 - k_f) l_0   (likewise alpha_z with R_z),
//     l_0 the parent segment's length, R_x and R_z its sway phases;
//   directed: every branch then turns toward the wind by alpha_w = (S_0 / S) w_g, S_0 the
//     tips above its parent and S those of the tree;
//   gravimorphism (the joint's alpha_m) bends toward the down vertical as seen from the
//     parent's frame without directed wind, as Algorithm 1's M_m^{-1} does.
// Rotations accumulate from the root; each segment keeps its length and joint, and leaves
// already on the skeleton move with their segment.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "model/skeleton.hpp"
#include "model/species.hpp"
#include "model/tree_build_options.hpp"

namespace eco {

struct Wind {
  double directed_wg = 0.0;             // degrees at S_0 = S
  double undirected_ws = 0.0;           // degrees per metre of parent branch
  glm::dvec3 direction{0.0, 1.0, 0.0};  // toward which the wind blows (tree frame)
  double flexibility = 1.0;             // k_f: sway scales with 1 - k_f
  double time = 0.0;                    // t, radians
  bool calm() const { return directed_wg == 0.0 && (undirected_ws == 0.0 || flexibility >= 1.0); }
};

// The species' wind with the build options' overrides and time.
Wind windOf(const Species& species, const TreeBuildOptions& options);

// Sets every frame and start from the joints under `wind`; the strand model poses its
// skeleton through this even in a calm.
void poseSkeleton(TreeSkeleton& skeleton, const Wind& wind);

// The wind on a skeleton whose frames are already posed at rest: does nothing in a calm (the
// skeleton stays bit-identical), else poseSkeleton.
void applyWind(TreeSkeleton& skeleton, const Wind& wind);

// Gives every segment sway phases R_x, R_z from the individual's seed, for a generator that
// has none of its own (an L-system).
void assignSwayPhases(TreeSkeleton& skeleton, std::uint64_t seed);

}  // namespace eco
