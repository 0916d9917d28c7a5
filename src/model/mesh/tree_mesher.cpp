#include "model/mesh/tree_mesher.hpp"

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

float leafCardAspect(LeafShape shape) {
  return shape == LeafShape::NeedleTuft ? 0.9f : 0.6f;
}

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
    for (auto s = static_cast<std::int32_t>(first);
         s >= 0 && segments[s].strands >= options.minStrands; s = majorChild[s])
      chain.push_back(s);

    // Thick chains get more sides; sqrt keeps mid-sized branches round.
    int sides = static_cast<int>(
        std::lround(options.maxSides * std::sqrt(head.startRadius_m / rootRadius)));
    sides = std::clamp(sides, options.minSides, options.maxSides);
    const std::size_t rings = chain.size() + 1;
    const float circumference =
        2.0f * std::numbers::pi_v<float> * std::max(head.startRadius_m, 1e-4f);

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
        float angle =
            2.0f * std::numbers::pi_v<float> * static_cast<float>(j) / static_cast<float>(sides);
        glm::vec3 out = std::cos(angle) * reference + std::sin(angle) * binormal;
        std::uint32_t v = bark.addVertex(
            center + radius * out, out,
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
    std::uint32_t lastRing =
        static_cast<std::uint32_t>(bark.positions.size()) - static_cast<std::uint32_t>(sides + 1);
    std::uint32_t apex = bark.addVertex(last.end() + last.axis() * last.endRadius_m, last.axis(),
                                        {0.5f, (travelled + last.endRadius_m) / circumference});
    for (int j = 0; j < sides; ++j) bark.addTriangle(lastRing + j, lastRing + j + 1, apex);
    if (head.parent < 0) {
      std::uint32_t center = bark.addVertex(head.start, -head.axis(), {0.5f, 0.0f});
      for (int j = 0; j < sides; ++j)
        bark.addTriangle(firstVertex + j + 1, firstVertex + j, center);
    }
  }
}

namespace {

// Writes cards straight into pre-sized arrays: a pine has 180000 leaves, and per-element
// push_back dominated the mesh time.
class CardWriter {
 public:
  CardWriter(MeshPart& part, std::size_t cards) : part_(part), vertex_(part.positions.size()) {
    std::size_t vertices = vertex_ + 4 * cards;
    part.positions.resize(vertices);
    part.normals.resize(vertices);
    part.uvs.resize(vertices);
    index_ = part.indices.size();
    part.indices.resize(index_ + 6 * cards);
  }

  void add(glm::vec3 base, glm::vec3 along, glm::vec3 across, float length, float width) {
    glm::vec3 normal = glm::normalize(glm::cross(across, along));
    glm::vec3 half = across * (0.5f * width);
    glm::vec3 tip = base + along * length;
    glm::vec3* p = &part_.positions[vertex_];
    p[0] = base - half;
    p[1] = base + half;
    p[2] = tip + half;
    p[3] = tip - half;
    glm::vec3* n = &part_.normals[vertex_];
    n[0] = n[1] = n[2] = n[3] = normal;
    glm::vec2* t = &part_.uvs[vertex_];
    t[0] = {0.0f, 0.0f};
    t[1] = {1.0f, 0.0f};
    t[2] = {1.0f, 1.0f};
    t[3] = {0.0f, 1.0f};
    auto v = static_cast<std::uint32_t>(vertex_);
    std::uint32_t* i = &part_.indices[index_];
    i[0] = v, i[1] = v + 1, i[2] = v + 2, i[3] = v, i[4] = v + 2, i[5] = v + 3;
    vertex_ += 4;
    index_ += 6;
  }

 private:
  MeshPart& part_;
  std::size_t vertex_;
  std::size_t index_;
};

}  // namespace

void meshLeaves(const TreeSkeleton& skeleton, LeafShape shape, MeshPart& cards, MeshPart& needles) {
  const float aspect = leafCardAspect(shape);
  std::size_t needleCount = 0;
  for (const Leaf& leaf : skeleton.leaves) needleCount += leaf.kind == LeafKind::Needle ? 1 : 0;
  CardWriter cardWriter(cards, skeleton.leaves.size() - needleCount);
  CardWriter needleWriter(needles, 2 * needleCount);
  for (const Leaf& leaf : skeleton.leaves) {
    // across = direction x normal makes the card's front face the leaf's normal; both are
    // unit and perpendicular, so across is a unit vector too.
    glm::vec3 across = glm::cross(leaf.direction, leaf.normal);
    if (leaf.kind == LeafKind::Needle) {
      float width = leaf.size_m * kNeedleAspect;
      needleWriter.add(leaf.position, leaf.direction, across, leaf.size_m, width);
      needleWriter.add(leaf.position, leaf.direction, leaf.normal, leaf.size_m, width);
    } else {
      cardWriter.add(leaf.position, leaf.direction, across, leaf.size_m, leaf.size_m * aspect);
    }
  }
}

TreeMesh meshTree(const TreeSkeleton& skeleton, const MeshOptions& options) {
  TreeMesh mesh;
  meshTreeInto(skeleton, options, mesh);
  return mesh;
}

void meshTreeInto(const TreeSkeleton& skeleton, const MeshOptions& options, TreeMesh& mesh) {
  // Parts of other materials (from an earlier LOD) are dropped; ours keep their capacity.
  std::erase_if(mesh.parts, [](const MeshPart& part) {
    return part.material != MaterialKind::Bark && part.material != MaterialKind::Leaf &&
           part.material != MaterialKind::Needle;
  });
  mesh.parts.reserve(mesh.parts.size() + 3);  // the references below must stay valid
  MeshPart& bark = mesh.reusePart(MaterialKind::Bark);
  MeshPart& cards = mesh.reusePart(MaterialKind::Leaf);
  MeshPart& needles = mesh.reusePart(MaterialKind::Needle);
  // An upper bound keeps the bark arrays from reallocating on the hot path: every segment
  // adds at most one ring, every chain a cap and a tip. Leaf arrays are sized exactly.
  const std::size_t sides = static_cast<std::size_t>(options.maxSides);
  bark.reserve(skeleton.segments.size() * (sides + 1) * 2 + 2,
               skeleton.segments.size() * sides * 4);
  meshBranches(skeleton, options, bark);
  if (options.leaves) meshLeaves(skeleton, options.leafShape, cards, needles);
  mesh.dropEmptyParts();
}

}  // namespace eco
