// EcoMod's strand tree model: Algorithm 1 of Zamuda et al. builds the branch structure by
// recursively splitting S strands into a major and a minor sub-branch until single strands
// remain, which carry the leaves. docs/model.md gives every formula and each reading we
// chose where the paper is ambiguous.
#pragma once

#include "model/skeleton.hpp"
#include "model/species.hpp"
#include "model/tree_build_options.hpp"

namespace eco {

// The development a seedling (age 0) already has (growth rule in docs/model.md).
inline constexpr double kSeedlingFraction = 0.04;

TreeSkeleton buildStrandTree(const Species& species, const TreeBuildOptions& options);
// The same into a skeleton the caller owns: its arrays keep their capacity, so building
// many trees one after another allocates (and page-faults) nothing new.
void buildStrandTreeInto(const Species& species, const TreeBuildOptions& options,
                         TreeSkeleton& out);

}  // namespace eco
