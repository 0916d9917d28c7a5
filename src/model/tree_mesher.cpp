#include "model/tree_mesher.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace eco {
namespace {

glm::vec3 perpendicularTo(glm::vec3 reference, glm::vec3 tangent, glm::vec3 fallback) {
  glm::vec3 r = reference - glm::dot(reference, tangent) * tangent;
  float len = glm::length(r);
  if (len > 1e-5f) return r / len;
  r = fallback - glm::dot(fallback, tangent) * tangent;
  return glm::normalize(r);
}

}  // namespace

void addCard(MeshPart& part, glm::vec3 base, glm::vec3 along, glm::vec3 across, float length,
             float width) {
  glm::vec3 normal = glm::normalize(glm::cross(across, along));
  glm::vec3 half = across * (0.5f * width);
  glm::vec3 tip = base + along * length;
  std::uint32_t a = part.addVertex(base - half, normal, {0.0f, 0.0f});
  std::uint32_t b = part.addVertex(base + half, normal, {1.0f, 0.0f});
  std::uint32_t c = part.addVertex(tip + half, normal, {1.0f, 1.0f});
  std::uint32_t d = part.addVertex(tip - half, normal, {0.0f, 1.0f});
  part.addTriangle(a, b, c);
  part.addTriangle(a, c, d);
}

float leafCardAspect(LeafShape shape) { return shape == LeafShape::NeedleTuft ? 0.9f : 0.6f; }

void meshBranches(const TreeSkeleton& skeleton, const MeshOptions& options, MeshPart& bark) {
  const auto& segments = skeleton.segments;
  if (segments.empty()) return;
  std::vector<std::int32_t> majorChild(segments.size(), -1);
  for (std::size_t i = 1; i < segments.size(); ++i)
    if (segments[i].continuesParent) majorChild[segments[i].parent] = static_cast<std::int32_t>(i);

  const float rootRadius = std::max(segments.front().startRadius_m, 1e-6f);
  std::vector<std::int32_t> chain;
  for (std::size_t first = 0; first < segments.size(); ++first) {
    const BranchSegment& head = segments[first];
    if (head.continuesParent || head.strands < options.minStrands) continue;
    chain.clear();
    for (auto s = static_cast<std::int32_t>(first); s >= 0 && segments[s].strands >= options.minStrands;
         s = majorChild[s])
      chain.push_back(s);

    // Thick chains get more sides; sqrt keeps mid-sized branches round.
    int sides = static_cast<int>(std::lround(options.maxSides * std::sqrt(head.startRadius_m / rootRadius)));
    sides = std::clamp(sides, options.minSides, options.maxSides);
    const std::size_t rings = chain.size() + 1;
    const float circumference = 2.0f * std::numbers::pi_v<float> * std::max(head.startRadius_m, 1e-4f);

    glm::vec3 reference = head.frame[0];
    float travelled = 0.0f;
    std::uint32_t firstVertex = 0;
    for (std::size_t k = 0; k < rings; ++k) {
      const BranchSegment& before = segments[chain[k == 0 ? 0 : k - 1]];
      const BranchSegment& after = segments[chain[std::min(k, chain.size() - 1)]];
      glm::vec3 center = k == 0 ? head.start : before.end();
      float radius = k == 0 ? head.startRadius_m : before.endRadius_m;
      glm::vec3 tangent = glm::normalize(before.axis() + after.axis());
      if (k > 0) travelled += before.length_m;
      reference = perpendicularTo(reference, tangent, after.frame[2]);
      glm::vec3 binormal = glm::cross(tangent, reference);
      std::uint32_t ringStart = 0;
      for (int j = 0; j <= sides; ++j) {  // j == sides duplicates j == 0 for the texture seam
        float angle = 2.0f * std::numbers::pi_v<float> * static_cast<float>(j) / static_cast<float>(sides);
        glm::vec3 out = std::cos(angle) * reference + std::sin(angle) * binormal;
        std::uint32_t v = bark.addVertex(center + radius * out, out,
                                         {static_cast<float>(j) / static_cast<float>(sides), travelled / circumference});
        if (j == 0) ringStart = v;
      }
      if (k == 0) firstVertex = ringStart;
      if (k > 0) {
        std::uint32_t previous = ringStart - static_cast<std::uint32_t>(sides + 1);
        for (int j = 0; j < sides; ++j) {
          std::uint32_t a = previous + j, b = previous + j + 1;
          std::uint32_t c = ringStart + j + 1, d = ringStart + j;
          bark.addTriangle(a, b, c);
          bark.addTriangle(a, c, d);
        }
      }
    }
    // Close the tip with a cone to an apex; close the stem base with a flat cap.
    const BranchSegment& last = segments[chain.back()];
    std::uint32_t lastRing = static_cast<std::uint32_t>(bark.positions.size()) - static_cast<std::uint32_t>(sides + 1);
    std::uint32_t apex = bark.addVertex(last.end() + last.axis() * last.endRadius_m, last.axis(),
                                        {0.5f, (travelled + last.endRadius_m) / circumference});
    for (int j = 0; j < sides; ++j) bark.addTriangle(lastRing + j, lastRing + j + 1, apex);
    if (head.parent < 0) {
      std::uint32_t center = bark.addVertex(head.start, -head.axis(), {0.5f, 0.0f});
      for (int j = 0; j < sides; ++j) bark.addTriangle(firstVertex + j + 1, firstVertex + j, center);
    }
  }
}

void meshLeaves(const TreeSkeleton& skeleton, LeafShape shape, MeshPart& cards, MeshPart& needles) {
  const float aspect = leafCardAspect(shape);
  for (const Leaf& leaf : skeleton.leaves) {
    // across = direction x normal makes the card's front face the leaf's normal.
    glm::vec3 across = glm::normalize(glm::cross(leaf.direction, leaf.normal));
    if (leaf.kind == LeafKind::Needle) {
      float width = leaf.size_m * kNeedleAspect;
      addCard(needles, leaf.position, leaf.direction, across, leaf.size_m, width);
      addCard(needles, leaf.position, leaf.direction, leaf.normal, leaf.size_m, width);
    } else {
      addCard(cards, leaf.position, leaf.direction, across, leaf.size_m, leaf.size_m * aspect);
    }
  }
}

TreeMesh meshTree(const TreeSkeleton& skeleton, const MeshOptions& options) {
  TreeMesh mesh;
  MeshPart bark{MaterialKind::Bark, {}, {}, {}, {}};
  MeshPart cards{MaterialKind::Leaf, {}, {}, {}, {}};
  MeshPart needles{MaterialKind::Needle, {}, {}, {}, {}};
  // Rough upper bounds keep the arrays from reallocating on the hot path.
  bark.positions.reserve(skeleton.segments.size() * (options.maxSides + 2));
  cards.positions.reserve(skeleton.leaves.size() * 4);
  meshBranches(skeleton, options, bark);
  if (options.leaves) meshLeaves(skeleton, options.leafShape, cards, needles);
  for (MeshPart* part : {&bark, &cards, &needles})
    if (!part->indices.empty()) mesh.parts.push_back(std::move(*part));
  return mesh;
}

}  // namespace eco
