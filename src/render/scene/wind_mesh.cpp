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

TreeSkeleton restSkeleton(const Species& species, std::uint64_t seed, double age,
                          double clearBole) {
  TreeBuildOptions options = windBuildOptions(species, seed, age, TreeWind{}, 0.0);
  options.clearBole = clearBole;
  TreeSkeleton skeleton;
  buildTreeInto(species, options, skeleton);
  return skeleton;
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
    bool topologyKept = windBases;
    for (std::size_t w = 1; w < poses; ++w) {
      const TreeMesh& other = meshes[w][m];
      topologyKept = topologyKept && other.parts.size() == rest.parts.size();
      for (std::size_t p = 0; topologyKept && p < rest.parts.size(); ++p)
        topologyKept = other.parts[p].positions.size() == rest.parts[p].positions.size() &&
                       other.parts[p].material == rest.parts[p].material;
    }
    if (!topologyKept && windBases && windless) ++*windless;
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
          return topologyKept ? meshes[w][m].parts[p].positions[v] - part.positions[v]
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

glm::vec2 LeanResponse::basesFor(glm::vec2 lean_wg) const {
  const float length = glm::length(lean_wg);
  if (length <= 0.0f) return glm::vec2(0.0f);
  // Through (0, 0), (kBendBasis_wg, 1) and the samples; past the last, its segment goes on.
  const std::array<float, 3> at{static_cast<float>(kBendBasis_wg),
                                static_cast<float>(kLeanSamples_wg[0]),
                                static_cast<float>(kLeanSamples_wg[1])};
  const std::array<float, 3> multiple{1.0f, bend[0], bend[1]};
  float bases = length / at[0];
  for (std::size_t i = 1; i < at.size() && length > at[i - 1]; ++i)
    bases = multiple[i - 1] +
            (length - at[i - 1]) * (multiple[i] - multiple[i - 1]) / (at[i] - at[i - 1]);
  return lean_wg / length * bases;
}

FoliageCentre foliageCentre(const WindMesh& mesh) {
  FoliageCentre centre;
  std::size_t count = 0;
  for (const WindPart& part : mesh.parts) {
    if (part.material == MaterialKind::Bark) continue;
    for (const TreeVertex& v : part.vertices)
      centre.position += glm::dvec3(v.position), centre.bendEast += glm::dvec3(v.bendEast);
    count += part.vertices.size();
  }
  if (count > 0) {
    centre.position /= static_cast<double>(count);
    centre.bendEast /= static_cast<double>(count);
  }
  return centre;
}

glm::dvec3 foliageCentre(const TreeMesh& mesh) {
  glm::dvec3 sum(0.0);
  std::size_t count = 0;
  for (const MeshPart& part : mesh.parts) {
    if (part.material == MaterialKind::Bark) continue;
    for (const glm::vec3& p : part.positions) sum += glm::dvec3(p);
    count += part.positions.size();
  }
  return count > 0 ? sum / static_cast<double>(count) : sum;
}

bool sameTopology(const WindMesh& rest, const TreeMesh& mesh) {
  if (mesh.parts.size() != rest.parts.size()) return false;
  for (std::size_t p = 0; p < rest.parts.size(); ++p)
    if (mesh.parts[p].positions.size() != rest.parts[p].vertices.size() ||
        mesh.parts[p].material != rest.parts[p].material)
      return false;
  return true;
}

LeanResponse measureLeanResponse(const Species& species, std::uint64_t seed, double age,
                                 double clearBole, const WindMesh& lod0) {
  LeanResponse response;
  const FoliageCentre rest = foliageCentre(lod0);
  const double perBasis = rest.bendEast.x;
  if (std::abs(perBasis) < 1e-6) return response;
  TreeSkeleton skeleton;
  TreeMesh mesh;
  for (std::size_t i = 0; i < kLeanSamples_wg.size(); ++i) {
    TreeBuildOptions options =
        windBuildOptions(species, seed, age, TreeWind{0.0, {kLeanSamples_wg[i], 0.0}}, 0.0);
    options.clearBole = clearBole;
    buildTreeInto(species, options, skeleton);
    buildLodInto(skeleton, species, 0, mesh);
    if (!sameTopology(lod0, mesh)) return LeanResponse{};
    response.bend[i] = static_cast<float>((foliageCentre(mesh).x - rest.position.x) / perBasis);
  }
  return response;
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
