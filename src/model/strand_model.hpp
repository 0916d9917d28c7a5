// EcoMod's strand tree model: Algorithm 1 of Zamuda et al. builds the branch structure by
// recursively splitting S strands into a major and a minor sub-branch until single strands
// remain, which carry the leaves. docs/model.md gives every formula and each reading we
// chose where the paper is ambiguous.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

#include "model/skeleton.hpp"
#include "model/species.hpp"

namespace eco {

struct TreeBuildOptions {
  std::uint64_t seed = 1;  // the individual: phases and small variations
  double age = 1.0;        // 0 = seedling, 1 = mature (growth rule in docs/model.md)
  double windTime = 0.0;   // t in alpha_x(t), alpha_z(t), radians of the sway oscillation
  // Wind overrides; unset means the species file's values.
  std::optional<double> windDirected;       // w_g
  std::optional<double> windUndirected;     // w_s
  std::optional<glm::dvec3> windDirection;  // w, toward which the wind blows (tree frame)
  bool leaves = true;
};

// The development a seedling (age 0) already has (growth rule in docs/model.md).
inline constexpr double kSeedlingFraction = 0.04;

TreeSkeleton buildStrandTree(const Species& species, const TreeBuildOptions& options);
// The same into a skeleton the caller owns: its arrays keep their capacity, so building
// many trees one after another allocates (and page-faults) nothing new.
void buildStrandTreeInto(const Species& species, const TreeBuildOptions& options,
                         TreeSkeleton& out);

// The horizontal direction toward which a wind blows that comes from compass bearing
// `fromDeg` (0 north, 90 east), in the tree frame (x east, y up, z south).
glm::dvec3 windTowardFromBearing(double fromDeg);

}  // namespace eco
