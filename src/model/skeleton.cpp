#include "model/skeleton.hpp"

#include <algorithm>
#include <cmath>

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

}  // namespace eco
