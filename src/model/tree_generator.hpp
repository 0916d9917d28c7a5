// One entry point for every tree generator: the EcoMod strand model (strand_model.hpp) or
// an RL-system grammar (lsystem_*.hpp), chosen by the species' `generator`. Meshing,
// levels of detail, exporters, the renderer and the ecosystem call only this.
#pragma once

#include "model/skeleton.hpp"
#include "model/species.hpp"
#include "model/tree_build_options.hpp"

namespace eco {

TreeSkeleton buildTree(const Species& species, const TreeBuildOptions& options);
void buildTreeInto(const Species& species, const TreeBuildOptions& options, TreeSkeleton& out);

// Derivation steps of an L-system species at `age` (0 seedling .. 1 mature): the mature
// count scaled by age, at least one.
int lsystemIterationsForAge(int matureIterations, double age);

// Scales a skeleton built in turtle units to metres.
void scaleSkeleton(TreeSkeleton& skeleton, float metresPerUnit);

}  // namespace eco
