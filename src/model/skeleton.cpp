#include "model/skeleton.hpp"

#include <algorithm>
#include <cmath>

#include <glm/matrix.hpp>

namespace eco {

SkeletonMeasures measure(const TreeSkeleton& skeleton) {
  SkeletonMeasures m;
  m.segments = skeleton.segments.size();
  auto extend = [&m](glm::vec3 p) {
    m.height_m = std::max(m.height_m, static_cast<double>(p.y));
    m.crownRadius_m =
        std::max(m.crownRadius_m, std::hypot(static_cast<double>(p.x), static_cast<double>(p.z)));
  };
  for (const BranchSegment& s : skeleton.segments) {
    if (s.isTerminal()) ++m.terminalSegments;
    m.maxGravelius = std::max<int>(m.maxGravelius, s.gravelius);
    m.maxWeibull = std::max<int>(m.maxWeibull, s.weibull);
    extend(s.end());
  }
  for (const Leaf& leaf : skeleton.leaves) extend(leaf.position + leaf.direction * leaf.size_m);
  if (!skeleton.segments.empty()) m.trunkDiameter_m = 2.0 * skeleton.segments.front().startRadius_m;
  return m;
}

void deriveJoints(TreeSkeleton& skeleton) {
  for (BranchSegment& s : skeleton.segments) {
    if (s.parent < 0) continue;
    const BranchSegment& parent = skeleton.segments[static_cast<std::size_t>(s.parent)];
    const glm::mat3 parentFromWorld = glm::transpose(parent.frame);
    s.twist = parentFromWorld * s.frame;
    s.bend_deg = 0.0;
    s.gravimorphism_deg = 0.0;
    s.atParentTip = false;
    s.offset_parent = parentFromWorld * (s.start - parent.start);
  }
}

}  // namespace eco
