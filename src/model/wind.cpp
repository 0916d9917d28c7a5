#include "model/wind.hpp"

#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/angles.hpp"
#include "core/random.hpp"
#include "core/rotation.hpp"

namespace eco {

Wind windOf(const Species& species, const TreeBuildOptions& options) {
  const WindParams& p = species.wind;
  Wind wind;
  wind.directed_wg = options.windDirected.value_or(p.directed_wg);
  wind.undirected_ws = options.windUndirected.value_or(p.undirected_ws);
  wind.direction = options.windDirection.value_or(p.direction);
  if (options.lean != glm::dvec2(0.0)) {  // the site's shaping turns the directed vector
    glm::dvec3 directed = glm::length(wind.direction) > 0.0
                              ? glm::normalize(wind.direction) * wind.directed_wg
                              : glm::dvec3(0.0);
    directed += glm::dvec3(options.lean.x, 0.0, options.lean.y);
    wind.directed_wg = glm::length(directed);
    wind.direction = directed;
  }
  wind.flexibility = p.flexibility;
  wind.time = options.windTime;
  return wind;
}

void poseSkeleton(TreeSkeleton& skeleton, const Wind& wind) {
  auto& segments = skeleton.segments;
  const std::size_t n = segments.size();
  if (n == 0) return;
  double totalStrands = 0.0;
  for (const BranchSegment& s : segments)
    if (s.parent < 0) totalStrands += s.strands;
  const double sway = wind.undirected_ws * (1.0 - wind.flexibility);
  const glm::vec3 toward = glm::length(wind.direction) > 0.0
                               ? glm::vec3(glm::normalize(wind.direction))
                               : glm::vec3(0.0f);
  const glm::vec3 gravity(0.0f, -1.0f, 0.0f);

  // Leaves on the skeleton keep their place on their segment's frame as it was.
  std::vector<glm::mat3> restFrame;
  std::vector<glm::vec3> restStart;
  if (!skeleton.leaves.empty()) {
    restFrame.reserve(n);
    restStart.reserve(n);
    for (const BranchSegment& s : segments) {
      restFrame.push_back(s.frame);
      restStart.push_back(s.start);
    }
  }
  // Each segment's frame without directed wind (M_m^{-1} inverted), for gravimorphism.
  std::vector<glm::mat3> gravimorphicFrame(n);
  for (std::size_t i = 0; i < n; ++i) {
    BranchSegment& s = segments[i];
    if (s.parent < 0) {  // the stem base stands
      gravimorphicFrame[i] = s.frame;
      continue;
    }
    const auto p = static_cast<std::size_t>(s.parent);
    const BranchSegment& parent = segments[p];
    const double alphaX = std::sin(wind.time + parent.windPhaseX) * sway * parent.length_m;
    const double alphaZ = std::sin(wind.time + parent.windPhaseZ) * sway * parent.length_m;
    const glm::vec3 gravityLocal = glm::transpose(gravimorphicFrame[p]) * gravity;
    const glm::mat3 local = tiltToward(gravityLocal, s.gravimorphism_deg) * s.twist *
                            rotationX(alphaX) * rotationZ(s.bend_deg + alphaZ);
    gravimorphicFrame[i] = gravimorphicFrame[p] * local;
    const glm::mat3 beforeWind = parent.frame * local;
    const double alphaW =
        totalStrands > 0.0 ? parent.strands / totalStrands * wind.directed_wg : 0.0;
    s.frame = beforeWind * tiltToward(glm::transpose(beforeWind) * toward, alphaW);
    s.start = s.atParentTip ? parent.end() : parent.start + parent.frame * s.offset_parent;
  }
  for (Leaf& leaf : skeleton.leaves) {
    const auto s = static_cast<std::size_t>(leaf.segment);
    const glm::mat3 turn = segments[s].frame * glm::transpose(restFrame[s]);
    leaf.position = segments[s].start + turn * (leaf.position - restStart[s]);
    leaf.direction = turn * leaf.direction;
    leaf.normal = turn * leaf.normal;
  }
}

void applyWind(TreeSkeleton& skeleton, const Wind& wind) {
  if (!wind.calm()) poseSkeleton(skeleton, wind);
}

void assignSwayPhases(TreeSkeleton& skeleton, std::uint64_t seed) {
  constexpr std::uint64_t kPhases = purpose("skeleton.sway");
  for (std::size_t i = 0; i < skeleton.segments.size(); ++i) {
    BranchSegment& s = skeleton.segments[i];
    Rng rng(streamKey(seed, i, kPhases));
    s.windPhaseX = static_cast<float>(2.0 * kPi * rng.uniform());
    s.windPhaseZ = static_cast<float>(2.0 * kPi * rng.uniform());
  }
}

}  // namespace eco
