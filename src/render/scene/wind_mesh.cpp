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

WindLods buildWindLods(const Species& species, std::uint64_t seed, double age) {
  const double quarter = 0.5 * std::numbers::pi;
  const std::array<TreeWind, 5> winds{TreeWind{},                       // rest
                                      TreeWind{kSwayBasis_ws, {0, 0}},  // t = pi / 2
                                      TreeWind{kSwayBasis_ws, {0, 0}},  // t = 0
                                      TreeWind{0.0, {kBendBasis_wg, 0}},
                                      TreeWind{0.0, {0, kBendBasis_wg}}};
  const std::array<double, 5> times{0.0, quarter, 0.0, 0.0, 0.0};

  WindLods result;
  std::array<std::array<TreeMesh, kLodCount>, 5> meshes;
  TreeSkeleton skeleton;
  for (std::size_t w = 0; w < winds.size(); ++w) {
    buildTreeInto(species, windBuildOptions(species, seed, age, winds[w], times[w]), skeleton);
    for (int lod = 0; lod < kLodCount; ++lod) buildLodInto(skeleton, species, lod, meshes[w][lod]);
  }
  for (int lod = 0; lod < kLodCount; ++lod) {
    const TreeMesh& rest = meshes[0][lod];
    bool sameTopology = true;
    for (std::size_t w = 1; w < winds.size(); ++w) {
      const TreeMesh& other = meshes[w][lod];
      sameTopology = sameTopology && other.parts.size() == rest.parts.size();
      for (std::size_t p = 0; sameTopology && p < rest.parts.size(); ++p)
        sameTopology = other.parts[p].positions.size() == rest.parts[p].positions.size() &&
                       other.parts[p].material == rest.parts[p].material;
    }
    if (!sameTopology) ++result.windless;
    WindMesh& out = result.lods[lod];
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
          return sameTopology ? meshes[w][lod].parts[p].positions[v] - part.positions[v]
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

}  // namespace eco
