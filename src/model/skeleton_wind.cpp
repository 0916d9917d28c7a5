#include "model/skeleton_wind.hpp"

#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "core/random.hpp"
#include "core/rotation.hpp"

namespace eco {

void applyWind(TreeSkeleton& skeleton, const SkeletonWind& wind) {
  auto& segments = skeleton.segments;
  const std::size_t n = segments.size();
  if (n == 0 || wind.calm()) return;
  constexpr std::uint64_t kPhases = purpose("skeleton.sway");
  double totalStrands = 0.0;
  for (const BranchSegment& s : segments)
    if (s.parent < 0) totalStrands += s.strands;
  const double sway = wind.undirected_ws * (1.0 - wind.flexibility);
  const glm::vec3 toward = glm::length(wind.direction) > 0.0
                               ? glm::vec3(glm::normalize(wind.direction))
                               : glm::vec3(0.0f);

  std::vector<glm::mat3> restFrame(n);
  std::vector<glm::vec3> restStart(n);
  for (std::size_t i = 0; i < n; ++i) {
    BranchSegment& s = segments[i];
    restFrame[i] = s.frame;
    restStart[i] = s.start;
    Rng rng(streamKey(wind.seed, i, kPhases));
    s.windPhaseX = static_cast<float>(2.0 * std::numbers::pi * rng.uniform());
    s.windPhaseZ = static_cast<float>(2.0 * std::numbers::pi * rng.uniform());
  }
  for (std::size_t i = 0; i < n; ++i) {
    BranchSegment& s = segments[i];
    if (s.parent < 0) continue;  // the stem base stands, as in the strand model
    const auto p = static_cast<std::size_t>(s.parent);
    const BranchSegment& parent = segments[p];
    const glm::mat3 local = glm::transpose(restFrame[p]) * restFrame[i];
    const double alphaX = std::sin(wind.time + parent.windPhaseX) * sway * parent.length_m;
    const double alphaZ = std::sin(wind.time + parent.windPhaseZ) * sway * parent.length_m;
    const glm::mat3 beforeWind = parent.frame * rotationX(alphaX) * rotationZ(alphaZ) * local;
    const double alphaW =
        totalStrands > 0.0 ? parent.strands / totalStrands * wind.directed_wg : 0.0;
    s.frame = beforeWind * tiltToward(glm::transpose(beforeWind) * toward, alphaW);
    s.start = parent.start +
              parent.frame * (glm::transpose(restFrame[p]) * (restStart[i] - restStart[p]));
  }
  for (Leaf& leaf : skeleton.leaves) {
    const auto s = static_cast<std::size_t>(leaf.segment);
    const glm::mat3 turn = segments[s].frame * glm::transpose(restFrame[s]);
    leaf.position = segments[s].start + turn * (leaf.position - restStart[s]);
    leaf.direction = turn * leaf.direction;
    leaf.normal = turn * leaf.normal;
  }
}

}  // namespace eco
