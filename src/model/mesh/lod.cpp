#include "model/mesh/lod.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "model/mesh/textures.hpp"
#include "model/mesh/tree_mesher.hpp"

namespace eco {
namespace {

MeshOptions lod0Options(const Species& species, int maxSides) {
  MeshOptions options;
  options.leafShape = species.appearance.leafShape;
  options.maxSides = maxSides;
  options.minSides = std::min(options.minSides, maxSides);
  return options;
}

// Needles under the same branch of at least kLod1ClusterStrands strands become one cluster
// of two crossed cards showing the same visible needle area.
void clusterNeedles(const TreeSkeleton& skeleton, const Species& species, MeshPart& clusters) {
  struct Cluster {
    glm::vec3 centroid{0.0f};
    glm::vec3 normal{0.0f};
    glm::vec3 direction{0.0f};
    float area_m2 = 0.0f;
    int count = 0;
  };
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
    c.area_m2 += visibleLeafArea(species, leaf.size_m);
    ++c.count;
  }
  for (std::int32_t branch : order) {  // first-seen order keeps the output deterministic
    const Cluster& c = byBranch[branch];
    glm::vec3 center = c.centroid / static_cast<float>(c.count);
    glm::vec3 normal =
        glm::length(c.normal) > 1e-4f ? glm::normalize(c.normal) : glm::vec3(0, 1, 0);
    glm::vec3 along = c.direction - glm::dot(c.direction, normal) * normal;
    if (glm::length(along) < 1e-4f) along = glm::cross(normal, glm::vec3(1, 0, 0));
    if (glm::length(along) < 1e-4f) along = glm::vec3(0, 0, 1);
    along = glm::normalize(along);
    glm::vec3 across = glm::cross(along, normal);
    // Two cards share the visible needle area; each shows its texture's coverage of it.
    float side = std::sqrt(c.area_m2 / (2.0f * kNeedleClusterCoverage));
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
    int j = static_cast<int>(azimuth / (2.0f * std::numbers::pi_v<float>)*kLon) % kLon;
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

  // Vertex (i, j) sits between latitude cells: it takes the largest reach among the cells
  // that touch it (so the leaves stay inside), averaged half-and-half with its ring
  // neighbours' to soften single spikes.
  auto cellReach = [&](int i, int j) {
    return reach[std::clamp(i, 0, kLat - 1) * kLon + ((j % kLon) + kLon) % kLon];
  };
  auto vertexReach = [&](int i, int j) {
    return std::max(
        {cellReach(i - 1, j - 1), cellReach(i - 1, j), cellReach(i, j - 1), cellReach(i, j)});
  };
  // Welded vertex id: the seam column j = kLon is j = 0, and each pole is one point.
  auto weldedId = [](int i, int j) {
    return i == 0 ? 0 : i == kLat ? 1 + (kLat - 1) * kLon : 1 + (i - 1) * kLon + j % kLon;
  };
  std::vector<glm::vec3> hull(2 + (kLat - 1) * kLon);
  for (int i = 0; i <= kLat; ++i) {
    float polar = std::numbers::pi_v<float> * static_cast<float>(i) / kLat;
    for (int j = 0; j < kLon; ++j) {
      float azimuth = 2.0f * std::numbers::pi_v<float> * static_cast<float>(j) / kLon -
                      std::numbers::pi_v<float>;
      glm::vec3 d(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                  std::sin(polar) * std::sin(azimuth));
      float r = 0.5f * vertexReach(i, j) + 0.25f * (vertexReach(i, j - 1) + vertexReach(i, j + 1));
      hull[weldedId(i, j)] = center + d * r;
    }
  }
  // Quads between rings; the first and last rows are fans at the poles.
  std::vector<std::array<int, 3>> triangles;
  for (int i = 0; i < kLat; ++i)
    for (int j = 0; j < kLon; ++j) {
      int a = weldedId(i, j), b = weldedId(i, j + 1), c = weldedId(i + 1, j + 1),
          d = weldedId(i + 1, j);
      if (i > 0) triangles.push_back({a, b, d});
      if (i < kLat - 1) triangles.push_back({b, c, d});
    }
  // Smooth normals: area-weighted face normals summed at each welded vertex.
  std::vector<glm::vec3> normals(hull.size(), glm::vec3(0.0f));
  for (const auto& t : triangles) {
    glm::vec3 n = glm::cross(hull[t[1]] - hull[t[0]], hull[t[2]] - hull[t[0]]);
    for (int v : t) normals[v] += n;
  }
  std::vector<std::uint32_t> vertex(hull.size());
  for (std::size_t v = 0; v < hull.size(); ++v) {
    glm::vec3 n = glm::length(normals[v]) > 0.0f ? glm::normalize(normals[v])
                                                 : glm::normalize(hull[v] - center);
    glm::vec3 d = glm::normalize(hull[v] - center);
    // Spherical UVs; the crown material is untextured, so the seam does not matter.
    glm::vec2 uv(0.5f + std::atan2(d.z, d.x) / (2.0f * std::numbers::pi_v<float>),
                 std::acos(std::clamp(d.y, -1.0f, 1.0f)) / std::numbers::pi_v<float>);
    vertex[v] = crown.addVertex(hull[v], n, uv);
  }
  for (const auto& t : triangles) crown.addTriangle(vertex[t[0]], vertex[t[1]], vertex[t[2]]);
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
    bark.addVertex(out * (0.7f * radius) + glm::vec3(0, top_m, 0), out,
                   {u, top_m / (2.0f * std::numbers::pi_v<float> * radius)});
  }
  for (std::uint32_t j = 0; j < kSides; ++j) {
    std::uint32_t a = 2 * j, b = 2 * j + 2, c = 2 * j + 3, d = 2 * j + 1;
    bark.addTriangle(a, b, c);
    bark.addTriangle(a, c, d);
  }
}

}  // namespace

bool bearsNeedles(const Species& species) {
  return species.strand.leafDistribution == LeafDistribution::Coniferous ||
         species.appearance.leafShape == LeafShape::NeedleTuft;
}

float visibleLeafArea(const Species& species, float size_m) {
  if (species.strand.leafDistribution == LeafDistribution::Coniferous)
    return 2.0f * size_m * size_m * kNeedleAspect * kNeedleCoverage;  // two crossed cards
  bool tuft = species.appearance.leafShape == LeafShape::NeedleTuft;
  return size_m * size_m * leafCardAspect(species.appearance.leafShape) *
         (tuft ? kNeedleTuftCoverage : kBroadleafCoverage);
}

TreeMesh buildLod(const TreeSkeleton& skeleton, const Species& species, int lod, int maxSides) {
  TreeMesh mesh;
  buildLodInto(skeleton, species, lod, mesh, maxSides);
  return mesh;
}

void buildLodInto(const TreeSkeleton& skeleton, const Species& species, int lod, TreeMesh& mesh,
                  int maxSides) {
  ECO_ASSERT(lod >= 0 && lod < kLodCount, "lod=" << lod);
  ECO_ASSERT(maxSides >= 3, "maxSides=" << maxSides);
  if (lod == 0) {
    meshTreeInto(skeleton, lod0Options(species, maxSides), mesh);
    return;
  }
  if (lod == 1) {
    MeshOptions options = lod0Options(species, std::min(5, maxSides));
    // The strand model's thin twigs go; an L-system's segments are whole internodes that
    // carry its leaves, so dropping them would leave the leaves floating.
    options.minStrands = species.generator == TreeGenerator::Strand ? kLod1MinStrands : 1;
    // Broadleaves keep their own leaf cards: a few thousand, and the clustered cards that
    // stood in for them measured far from LOD0 wherever LOD1 is drawn (docs/model.md).
    options.leaves = !bearsNeedles(species);
    mesh = meshTree(skeleton, options);
    if (options.leaves) return;
    MeshPart clusters{MaterialKind::LeafCluster, {}, {}, {}, {}};
    clusterNeedles(skeleton, species, clusters);
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
