#include "model/design/hint.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace eco {

HintInterval pointInfluence(LocalGraph graph, const Polyline& line, int index) {
  const auto points = line.points();
  ECO_ASSERT(index >= 0 && index < static_cast<int>(points.size()), "point " << index);
  HintInterval hint{graph};
  hint.withEnds = false;
  if (index > 0) hint.lo = points[index - 1].x;
  if (index + 1 < static_cast<int>(points.size())) hint.hi = points[index + 1].x;
  return hint;
}

HintInterval segmentSpan(LocalGraph graph, const Polyline& line, int index) {
  const auto points = line.points();
  ECO_ASSERT(index >= 0 && index + 1 < static_cast<int>(points.size()), "segment " << index);
  return {graph, points[index].x, points[index + 1].x, true};
}

HintInterval wholeGraph(LocalGraph graph) {
  return HintInterval{graph};
}

std::vector<std::int32_t> hintedSegments(const TreeSkeleton& skeleton, const HintInterval& hint) {
  const bool gravelius = infoOf(hint.graph).over == BranchOrder::Gravelius;
  std::vector<std::int32_t> hinted;
  for (std::size_t i = 0; i < skeleton.segments.size(); ++i) {
    const BranchSegment& s = skeleton.segments[i];
    if (hint.contains(gravelius ? s.gravelius : s.weibull))
      hinted.push_back(static_cast<std::int32_t>(i));
  }
  return hinted;
}

MeshPart hintSleeves(const TreeSkeleton& skeleton, const std::vector<std::int32_t>& segments) {
  constexpr int kSides = 6;
  MeshPart part;
  part.material = MaterialKind::Bark;
  part.reserve(segments.size() * 2 * kSides, segments.size() * 2 * kSides);
  for (std::int32_t index : segments) {
    const BranchSegment& s = skeleton.segments[index];
    if (s.length_m <= 0.0f) continue;
    const glm::vec3 across = s.frame[0], depth = s.frame[2];
    const float radii[2] = {std::max(1.3f * s.startRadius_m, kHintMinRadius_m),
                            std::max(1.3f * s.endRadius_m, kHintMinRadius_m)};
    const glm::vec3 ends[2] = {s.start, s.end()};
    const auto first = static_cast<std::uint32_t>(part.positions.size());
    for (int end = 0; end < 2; ++end)
      for (int k = 0; k < kSides; ++k) {
        const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / kSides;
        const glm::vec3 normal = std::cos(a) * across + std::sin(a) * depth;
        part.addVertex(ends[end] + radii[end] * normal, normal,
                       {static_cast<float>(k) / kSides, static_cast<float>(end)});
      }
    for (std::uint32_t k = 0; k < kSides; ++k) {
      const std::uint32_t next = (k + 1) % kSides;
      part.addTriangle(first + k, first + kSides + next, first + next);
      part.addTriangle(first + k, first + kSides + k, first + kSides + next);
    }
  }
  return part;
}

}  // namespace eco
