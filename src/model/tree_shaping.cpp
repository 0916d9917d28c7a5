#include "model/tree_shaping.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

namespace eco {

namespace {

// `v` with its length capped at 1 (a site's inputs are 0..1; files are rounded).
glm::dvec2 atMostUnit(glm::dvec2 v) {
  const double length = glm::length(v);
  return length > 1.0 ? v / length : v;
}

}  // namespace

glm::dvec2 shapingLean(const SiteShaping& site) {
  return kPhototropism_wg * atMostUnit(site.light) + kWindLean_wg * atMostUnit(site.wind);
}

void pruneClearBole(TreeSkeleton& skeleton, double share) {
  auto& segments = skeleton.segments;
  const std::size_t n = segments.size();
  if (share <= 0.0 || n == 0) return;
  // Distance along the stem of each stem segment's start; -1 off the stem.
  std::vector<double> stemStart(n, -1.0);
  double stemLength = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const BranchSegment& s = segments[i];
    double start = -1.0;
    if (s.parent < 0) {
      start = 0.0;
    } else if (s.continuesParent && stemStart[static_cast<std::size_t>(s.parent)] >= 0.0) {
      const BranchSegment& parent = segments[static_cast<std::size_t>(s.parent)];
      start = stemStart[static_cast<std::size_t>(s.parent)] +
              (s.atParentTip ? parent.length_m : s.offset_parent.y);
    }
    stemStart[i] = start;
    if (start >= 0.0) stemLength = std::max(stemLength, start + s.length_m);
  }
  const double clear = share * stemLength;
  // Parents come before children: a segment goes with its parent, or as a side branch
  // starting below the clear height.
  std::vector<std::int32_t> newIndex(n, -1);
  std::int32_t kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const BranchSegment& s = segments[i];
    bool keep = true;
    if (s.parent >= 0) {
      const auto p = static_cast<std::size_t>(s.parent);
      const bool sideOfStem = stemStart[i] < 0.0 && stemStart[p] >= 0.0;
      const double start =
          stemStart[p] + (s.atParentTip ? segments[p].length_m : s.offset_parent.y);
      keep = newIndex[p] >= 0 && !(sideOfStem && start < clear);
    }
    if (keep) newIndex[i] = kept++;
  }
  if (kept == static_cast<std::int32_t>(n)) return;
  std::vector<BranchSegment> remaining;
  remaining.reserve(static_cast<std::size_t>(kept));
  for (std::size_t i = 0; i < n; ++i) {
    if (newIndex[i] < 0) continue;
    BranchSegment s = segments[i];
    if (s.parent >= 0) s.parent = newIndex[static_cast<std::size_t>(s.parent)];
    remaining.push_back(s);
  }
  segments = std::move(remaining);
  std::vector<Leaf> leaves;
  leaves.reserve(skeleton.leaves.size());
  for (Leaf leaf : skeleton.leaves) {
    const std::int32_t to = newIndex[static_cast<std::size_t>(leaf.segment)];
    if (to < 0) continue;
    leaf.segment = to;
    leaves.push_back(leaf);
  }
  skeleton.leaves = std::move(leaves);
}

}  // namespace eco
