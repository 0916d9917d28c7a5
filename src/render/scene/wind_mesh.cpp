#include "render/scene/wind_mesh.hpp"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace eco {

std::size_t WindMesh::triangleCount() const {
  std::size_t triangles = 0;
  for (const WindPart& part : parts) triangles += part.indices.size() / 3;
  return triangles;
}

TreeBuildOptions windBuildOptions(const Species& species, std::uint64_t seed, double age,
                                  const TreeWind& wind, double t) {
  TreeBuildOptions options;
  options.seed = seed;
  options.age = age;
  options.windTime = t;
  options.windUndirected = wind.sway_ws;
  const WindParams& p = species.wind;
  glm::dvec3 own(0.0);
  if (glm::length(p.direction) > 0.0) own = glm::normalize(p.direction) * p.directed_wg;
  const glm::dvec3 total = own + glm::dvec3(wind.directed.x, 0.0, wind.directed.y);
  options.windDirected = glm::length(total);
  options.windDirection = glm::length(total) > 0.0 ? total : glm::dvec3(0.0, 1.0, 0.0);
  return options;
}

std::vector<WindMesh> buildWindMeshes(const Species& species, std::uint64_t seed, double age,
                                      std::span<const SkeletonMesher> meshers, int* windless,
                                      TreeSkeleton* rest, bool windBases, double clearBole) {
  const double quarter = 0.5 * std::numbers::pi;
  const std::array<TreeWind, 5> winds{TreeWind{},                       // rest
                                      TreeWind{kSwayBasis_ws, {0, 0}},  // t = pi / 2
                                      TreeWind{kSwayBasis_ws, {0, 0}},  // t = 0
                                      TreeWind{0.0, {kBendBasis_wg, 0}},
                                      TreeWind{0.0, {0, kBendBasis_wg}}};
  const std::array<double, 5> times{0.0, quarter, 0.0, 0.0, 0.0};

  std::vector<WindMesh> result(meshers.size());
  std::array<std::vector<TreeMesh>, 5> meshes;
  TreeSkeleton skeleton;
  const std::size_t poses = windBases ? winds.size() : 1;
  for (std::size_t w = 0; w < poses; ++w) {
    TreeBuildOptions options = windBuildOptions(species, seed, age, winds[w], times[w]);
    options.clearBole = clearBole;
    buildTreeInto(species, options, skeleton);
    meshes[w].resize(meshers.size());
    for (std::size_t m = 0; m < meshers.size(); ++m) meshers[m](skeleton, meshes[w][m]);
    if (w == 0 && rest) *rest = skeleton;
  }
  for (std::size_t m = 0; m < meshers.size(); ++m) {
    const TreeMesh& rest = meshes[0][m];
    bool sameTopology = windBases;
    for (std::size_t w = 1; w < poses; ++w) {
      const TreeMesh& other = meshes[w][m];
      sameTopology = sameTopology && other.parts.size() == rest.parts.size();
      for (std::size_t p = 0; sameTopology && p < rest.parts.size(); ++p)
        sameTopology = other.parts[p].positions.size() == rest.parts[p].positions.size() &&
                       other.parts[p].material == rest.parts[p].material;
    }
    if (!sameTopology && windBases && windless) ++*windless;
    WindMesh& out = result[m];
    for (std::size_t p = 0; p < rest.parts.size(); ++p) {
      const MeshPart& part = rest.parts[p];
      WindPart& gpu = out.parts.emplace_back();
      gpu.material = part.material;
      gpu.indices.assign(part.indices.begin(), part.indices.end());
      gpu.vertices.resize(part.positions.size());
      for (std::size_t v = 0; v < part.positions.size(); ++v) {
        TreeVertex& vertex = gpu.vertices[v];
        vertex.position = part.positions[v];
        vertex.normal = part.normals[v];
        vertex.uv = part.uvs[v];
        auto offset = [&](std::size_t w) {
          return sameTopology ? meshes[w][m].parts[p].positions[v] - part.positions[v]
                              : glm::vec3(0.0f);
        };
        vertex.swaySin = offset(1);
        vertex.swayCos = offset(2);
        vertex.bendEast = offset(3);
        vertex.bendSouth = offset(4);
      }
    }
  }
  return result;
}

WindLods buildWindLods(const Species& species, std::uint64_t seed, double age, TreeSkeleton* rest,
                       double clearBole) {
  std::array<SkeletonMesher, kLodCount> levels;
  for (int lod = 0; lod < kLodCount; ++lod)
    levels[lod] = [&species, lod](const TreeSkeleton& skeleton, TreeMesh& mesh) {
      buildLodInto(skeleton, species, lod, mesh);
    };
  WindLods result;
  std::vector<WindMesh> meshes =
      buildWindMeshes(species, seed, age, levels, &result.windless, rest, true, clearBole);
  for (int lod = 0; lod < kLodCount; ++lod) result.lods[lod] = std::move(meshes[lod]);
  return result;
}

}  // namespace eco
