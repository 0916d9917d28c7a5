#include "model/lod.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "model/tree_mesher.hpp"

namespace eco {
namespace {

MeshOptions lod0Options(const Species& species) {
  MeshOptions options;
  options.leafShape = species.appearance.leafShape;
  return options;
}

// Leaves under the same branch of at least kLod1ClusterStrands strands become one cluster
// of two crossed cards with the same total leaf area.
void clusterLeaves(const TreeSkeleton& skeleton, const Species& species, MeshPart& clusters) {
  struct Cluster {
    glm::vec3 centroid{0.0f};
    glm::vec3 normal{0.0f};
    glm::vec3 direction{0.0f};
    float area_m2 = 0.0f;
    int count = 0;
  };
  const float aspect = species.strand.leafDistribution == LeafDistribution::Coniferous
                           ? kNeedleAspect
                           : leafCardAspect(species.appearance.leafShape);
  std::unordered_map<std::int32_t, Cluster> byBranch;
  std::vector<std::int32_t> order;
  for (const Leaf& leaf : skeleton.leaves) {
    std::int32_t s = leaf.segment;
    while (skeleton.segments[s].strands < kLod1ClusterStrands && skeleton.segments[s].parent >= 0)
      s = skeleton.segments[s].parent;
    auto [it, inserted] = byBranch.try_emplace(s);
    if (inserted) order.push_back(s);
    Cluster& c = it->second;
    c.centroid += leaf.position + leaf.direction * (0.5f * leaf.size_m);
    c.normal += leaf.normal;
    c.direction += leaf.direction;
    c.area_m2 += leaf.size_m * leaf.size_m * aspect;
    ++c.count;
  }
  for (std::int32_t branch : order) {  // first-seen order keeps the output deterministic
    const Cluster& c = byBranch[branch];
    glm::vec3 center = c.centroid / static_cast<float>(c.count);
    glm::vec3 normal = glm::length(c.normal) > 1e-4f ? glm::normalize(c.normal) : glm::vec3(0, 1, 0);
    glm::vec3 along = c.direction - glm::dot(c.direction, normal) * normal;
    if (glm::length(along) < 1e-4f) along = glm::cross(normal, glm::vec3(1, 0, 0));
    if (glm::length(along) < 1e-4f) along = glm::vec3(0, 0, 1);
    along = glm::normalize(along);
    glm::vec3 across = glm::cross(along, normal);
    // Two cards share the leaf area; each shows it at the texture's coverage.
    float side = std::sqrt(c.area_m2 / (2.0f * kClusterCoverage));
    addCard(clusters, center - along * (0.5f * side), along, across, side, side);
    addCard(clusters, center - along * (0.5f * side), along, normal, side, side);
  }
}

// A star-shaped hull: a latitude/longitude sphere around the leaf centroid whose radius in
// each direction is the farthest leaf seen near that direction.
// Returns the height of the hull's centre, where the stem proxy ends, hidden in the crown.
float crownHull(const TreeSkeleton& skeleton, MeshPart& crown) {
  constexpr int kLat = 10, kLon = 16;
  std::vector<glm::vec3> points;
  for (const Leaf& leaf : skeleton.leaves) {
    points.push_back(leaf.position);
    points.push_back(leaf.position + leaf.direction * leaf.size_m);
  }
  if (points.empty())
    for (const BranchSegment& s : skeleton.segments)
      if (s.isTerminal()) points.push_back(s.end());
  if (points.empty()) return 0.0f;
  glm::vec3 center(0.0f);
  for (glm::vec3 p : points) center += p;
  center /= static_cast<float>(points.size());

  auto cellOf = [](glm::vec3 d) {
    float polar = std::acos(std::clamp(d.y, -1.0f, 1.0f));  // 0 at the top
    float azimuth = std::atan2(d.z, d.x) + std::numbers::pi_v<float>;
    int i = std::clamp(static_cast<int>(polar / std::numbers::pi_v<float> * kLat), 0, kLat - 1);
    int j = static_cast<int>(azimuth / (2.0f * std::numbers::pi_v<float>) * kLon) % kLon;
    return std::pair{i, j};
  };
  std::vector<float> reach(kLat * kLon, 0.0f);
  for (glm::vec3 p : points) {
    glm::vec3 d = p - center;
    float r = glm::length(d);
    if (r < 1e-6f) continue;
    auto [i, j] = cellOf(d / r);
    reach[i * kLon + j] = std::max(reach[i * kLon + j], r);
  }
  // Empty cells take the mean of their non-empty neighbours, then a mild smoothing by max of
  // neighbours keeps thin protrusions inside the hull.
  float meanReach = 0.0f;
  int filled = 0;
  for (float r : reach)
    if (r > 0.0f) meanReach += r, ++filled;
  meanReach = filled > 0 ? meanReach / filled : 0.1f;
  for (float& r : reach)
    if (r == 0.0f) r = meanReach;

  // Vertex rings between latitude cells: vertex (i, j) takes the largest reach among the
  // cells that touch it.
  auto cellReach = [&](int i, int j) { return reach[std::clamp(i, 0, kLat - 1) * kLon + ((j % kLon) + kLon) % kLon]; };
  std::vector<std::uint32_t> ring;
  for (int i = 0; i <= kLat; ++i) {
    float polar = std::numbers::pi_v<float> * static_cast<float>(i) / kLat;
    for (int j = 0; j <= kLon; ++j) {
      float azimuth = 2.0f * std::numbers::pi_v<float> * static_cast<float>(j) / kLon - std::numbers::pi_v<float>;
      glm::vec3 d(std::sin(polar) * std::cos(azimuth), std::cos(polar), std::sin(polar) * std::sin(azimuth));
      float r = std::max({cellReach(i - 1, j - 1), cellReach(i - 1, j), cellReach(i, j - 1), cellReach(i, j)});
      glm::vec3 p = center + d * r;
      ring.push_back(crown.addVertex(p, d, {static_cast<float>(j) / kLon, static_cast<float>(i) / kLat}));
    }
  }
  for (int i = 0; i < kLat; ++i)
    for (int j = 0; j < kLon; ++j) {
      std::uint32_t a = ring[i * (kLon + 1) + j], b = ring[i * (kLon + 1) + j + 1];
      std::uint32_t c = ring[(i + 1) * (kLon + 1) + j + 1], d = ring[(i + 1) * (kLon + 1) + j];
      if (i > 0) crown.addTriangle(a, b, d);            // the top row is a fan at the pole
      if (i < kLat - 1) crown.addTriangle(b, c, d);     // the bottom row is a fan at the pole
    }
  return center.y;
}

void stemProxy(const TreeSkeleton& skeleton, float top_m, MeshPart& bark) {
  constexpr int kSides = 6;
  if (skeleton.segments.empty()) return;
  float radius = skeleton.segments.front().startRadius_m;
  top_m = std::max(top_m, skeleton.segments.front().length_m);
  for (int j = 0; j <= kSides; ++j) {
    float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(j) / kSides;
    glm::vec3 out(std::cos(a), 0.0f, -std::sin(a));
    float u = static_cast<float>(j) / kSides;
    bark.addVertex(out * radius, out, {u, 0.0f});
    bark.addVertex(out * (0.7f * radius) + glm::vec3(0, top_m, 0), out, {u, top_m / (2.0f * std::numbers::pi_v<float> * radius)});
  }
  for (std::uint32_t j = 0; j < kSides; ++j) {
    std::uint32_t a = 2 * j, b = 2 * j + 2, c = 2 * j + 3, d = 2 * j + 1;
    bark.addTriangle(a, b, c);
    bark.addTriangle(a, c, d);
  }
}

}  // namespace

TreeMesh buildLod(const TreeSkeleton& skeleton, const Species& species, int lod) {
  TreeMesh mesh;
  buildLodInto(skeleton, species, lod, mesh);
  return mesh;
}

void buildLodInto(const TreeSkeleton& skeleton, const Species& species, int lod, TreeMesh& mesh) {
  ECO_ASSERT(lod >= 0 && lod < kLodCount, "lod=" << lod);
  if (lod == 0) {
    meshTreeInto(skeleton, lod0Options(species), mesh);
    return;
  }
  if (lod == 1) {
    MeshOptions options = lod0Options(species);
    options.maxSides = 5;
    options.minStrands = kLod1MinStrands;
    options.leaves = false;
    mesh = meshTree(skeleton, options);
    MeshPart clusters{MaterialKind::LeafCluster, {}, {}, {}, {}};
    clusterLeaves(skeleton, species, clusters);
    if (!clusters.indices.empty()) mesh.parts.push_back(std::move(clusters));
    return;
  }
  mesh.parts.clear();
  MeshPart crown{MaterialKind::Crown, {}, {}, {}, {}};
  MeshPart bark{MaterialKind::Bark, {}, {}, {}, {}};
  float crownCenter_m = crownHull(skeleton, crown);
  stemProxy(skeleton, crownCenter_m, bark);
  for (MeshPart* part : {&bark, &crown})
    if (!part->indices.empty()) mesh.parts.push_back(std::move(*part));
}

}  // namespace eco
