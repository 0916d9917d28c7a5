#include "model/tree_generator.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "model/lsystem/deriver.hpp"
#include "model/lsystem/turtle.hpp"
#include "model/strand_model.hpp"
#include "model/tree_shaping.hpp"
#include "model/wind.hpp"

namespace eco {

int lsystemIterationsForAge(int matureIterations, double age) {
  const double scaled = std::clamp(age, 0.0, 1.0) * matureIterations;
  return std::max(1, static_cast<int>(std::lround(scaled)));
}

void scaleSkeleton(TreeSkeleton& skeleton, float metresPerUnit) {
  for (BranchSegment& s : skeleton.segments) {
    s.start *= metresPerUnit;
    s.length_m *= metresPerUnit;
    s.startRadius_m *= metresPerUnit;
    s.endRadius_m *= metresPerUnit;
  }
  for (Leaf& leaf : skeleton.leaves) {
    leaf.position *= metresPerUnit;
    leaf.size_m *= metresPerUnit;
  }
  deriveJoints(skeleton);  // the joints' offsets in metres too
}

void buildTreeInto(const Species& species, const TreeBuildOptions& options, TreeSkeleton& out) {
  if (species.generator == TreeGenerator::Strand) {
    buildStrandTreeInto(species, options, out);
    pruneClearBole(out, options.clearBole);
    return;
  }
  ECO_ASSERT(species.lsystem.grammar, "species=" << species.name);
  const LSystem& grammar = *species.lsystem.grammar;
  DeriveOptions derive;
  derive.seed = options.seed;
  derive.iterations = lsystemIterationsForAge(species.lsystem.iterations, options.age);
  out = interpretTree(grammar, eco::derive(grammar, derive));
  scaleSkeleton(out, static_cast<float>(species.lsystem.unit_m));
  if (!options.leaves) out.leaves.clear();
  // RL-systems have no wind of their own: EcoMod's bends the finished skeleton.
  assignSwayPhases(out, options.seed);
  applyWind(out, windOf(species, options));
  pruneClearBole(out, options.clearBole);
}

TreeSkeleton buildTree(const Species& species, const TreeBuildOptions& options) {
  TreeSkeleton skeleton;
  buildTreeInto(species, options, skeleton);
  return skeleton;
}

}  // namespace eco
