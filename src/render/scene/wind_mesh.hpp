// Tree meshes with their wind bases, ready for the GPU.
//
// EcoMod's wind turns every branch by small angles: the undirected sway
// alpha_x(t) = sin(t + R_x) w_s (1 - k_f) l_0 (likewise alpha_z), and the directed tilt
// (S_0 / S) w_g toward the wind. To first order in those angles a vertex moves by
//   sin(t) * swaySin + cos(t) * swayCos            (sway: a sum of sines over its branches)
// + wind_east * bendEast + wind_south * bendSouth  (directed: linear in the horizontal wind)
// and the four vectors per vertex are exact differences of meshes the CPU model builds:
// swaySin at t = pi/2, swayCos at t = 0 (with w_s = kSwayBasis_ws), the bends with a
// horizontal wind of kBendBasis_wg toward east and toward south, each minus the rest pose
// (the species' own directed growth, no sway, no horizontal wind). docs/rendering.md.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "model/mesh/lod.hpp"
#include "model/mesh/mesh.hpp"
#include "model/species.hpp"
#include "model/tree_generator.hpp"

namespace eco {

inline constexpr double kSwayBasis_ws = 1.0;  // w_s of the sway bases, degrees per metre
inline constexpr double kBendBasis_wg = 1.0;  // horizontal w_g of the bend bases

struct TreeVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
  glm::vec3 swaySin;
  glm::vec3 swayCos;
  glm::vec3 bendEast;
  glm::vec3 bendSouth;
  float skyVisibility = 1.0f;  // share of the sky's light reaching it through its own crown
};
static_assert(sizeof(TreeVertex) == 84);

struct WindPart {
  MaterialKind material = MaterialKind::Bark;
  std::vector<TreeVertex> vertices;
  std::vector<std::uint32_t> indices;
};

struct WindMesh {
  std::vector<WindPart> parts;
  std::size_t triangleCount() const;
};

// The wind of a scene in a tree's frame: w_s of the sway and the horizontal directed wind
// (w_g times the unit direction toward which it blows, x east and z south).
struct TreeWind {
  double sway_ws = 0.0;
  glm::dvec2 directed{0.0};  // (east, south)
};

// The CPU model's build options for one tree under a scene wind at time t: the species'
// directed growth and the horizontal wind add as vectors (docs/rendering.md).
TreeBuildOptions windBuildOptions(const Species& species, std::uint64_t seed, double age,
                                  const TreeWind& wind, double t);

// The tree's skeleton in its rest pose (no scene wind), as buildWindLods builds it: its
// measures without the meshes.
TreeSkeleton restSkeleton(const Species& species, std::uint64_t seed, double age,
                          double clearBole = 0.0);

// LOD0..2 of one tree with wind bases. Where a level's topology changes with the wind (it
// should not: wind only turns frames), its bases stay zero and `windless` counts it.
struct WindLods {
  std::array<WindMesh, kLodCount> lods;
  int windless = 0;
};
// `rest` receives the rest pose's skeleton (the tree library measures it).
// `clearBole`: the share of the stem whose side branches are pruned (tree_shaping.hpp).
WindLods buildWindLods(const Species& species, std::uint64_t seed, double age,
                       TreeSkeleton* rest = nullptr, double clearBole = 0.0);

// The same for any meshes of the tree: each mesher turns a posed skeleton into a mesh, and
// every mesh gets its wind bases from the same five skeletons (the designer's preview
// shows one level and the visual hint's sleeves). `windless` counts meshes whose topology
// changed with the wind (their bases stay zero); `rest` receives the rest pose's skeleton.
// Without `windBases` only the rest pose is built (a fifth of the work) and the bases stay
// zero: a tree that the scene's wind never moves.
using SkeletonMesher = std::function<void(const TreeSkeleton&, TreeMesh&)>;
// A steady lean (a site's shaping, tree_shaping.hpp) drawn through the bend bases. The bases
// are exact at kBendBasis_wg, but EcoMod turns each branch toward the directed vector, so a
// stronger lean moves a crown less than the bases' straight line says (a pine's crown centre
// moves 11 % of its height for 1.5 w_g and 28 % for 6, where the line gives 45 %:
// shaping_bench). A type's response holds, for leans of kLeanSamples_wg, the multiple of the
// bases that moves its foliage's centre as far as the model grown with that lean does;
// between the samples the multiple is interpolated linearly.
inline constexpr std::array<double, 2> kLeanSamples_wg{3.0, 6.0};
struct LeanResponse {
  std::array<float, 2> bend{3.0f, 6.0f};  // multiples of the bases at kLeanSamples_wg
  // The multiples of (bendEast, bendSouth) that draw a lean (east, south; w_g).
  glm::vec2 basesFor(glm::vec2 lean_wg) const;
};
// The mean of a mesh's foliage vertices (every part but bark): the crown's centre, and how
// far the east bend basis moves it. Zero for a mesh without foliage.
struct FoliageCentre {
  glm::dvec3 position{0.0};
  glm::dvec3 bendEast{0.0};
};
FoliageCentre foliageCentre(const WindMesh& mesh);
glm::dvec3 foliageCentre(const TreeMesh& mesh);
// Whether a posed mesh has the parts and vertices of `rest`, vertex for vertex.
bool sameTopology(const WindMesh& rest, const TreeMesh& mesh);

// Measures a type's response from its LOD0 with bases and the model grown with a lean of
// each sample toward east (a tree whose foliage the bases do not move keeps the line).
LeanResponse measureLeanResponse(const Species& species, std::uint64_t seed, double age,
                                 double clearBole, const WindMesh& lod0);

std::vector<WindMesh> buildWindMeshes(const Species& species, std::uint64_t seed, double age,
                                      std::span<const SkeletonMesher> meshers,
                                      int* windless = nullptr, TreeSkeleton* rest = nullptr,
                                      bool windBases = true, double clearBole = 0.0);

}  // namespace eco
