// What a frame is drawn with and what drawing it cost: the sun, the wind, the levels of
// detail and shadows asked for, and the statistics the back end reports. Plain settings
// without OpenGL, shared by the renderer, the time-lapse and the command line.
#pragma once

#include <array>
#include <cstddef>
#include <numeric>
#include <optional>

#include "render/scene/culling.hpp"
#include "render/scene/ground_cover.hpp"
#include "render/scene/shadow_cascades.hpp"
#include "render/scene/sun.hpp"
#include "sim/scenario.hpp"

namespace eco {

struct SceneWind {
  // Where the wind comes from (0 north, 90 east): a scenario's prevailing wind.
  double fromBearing_deg = Climate{}.prevailingWindFrom_deg;
  double directed_wg = 0.0;  // w_g of the horizontal wind
  double sway_ws = 0.0;      // w_s of the undirected sway
  double gust = 0.25;        // relative swing of the directed wind over time
  double time = 0.0;         // t of the sway, radians
};

struct RenderOptions {
  SunTime sun;
  SceneWind wind;
  LodSettings lod;
  bool shadows = true;
  ShadowReach shadowReach;  // the nearest and the farthest cascade's squares
  int shadowMapSize = 2048;
  std::optional<float> fogDensity;  // per metre; default clear air (100 km visibility)
  GroundCoverSettings groundCover;  // default none; the command line's by quality
  // Waits for the GPU at each pass's end and times it (FrameStats::passMs): which pass
  // costs what, for a benchmark. The wait splits the work the GPU would overlap, and a
  // tiled renderer such as llvmpipe draws each pass as its own scene, so the frame as a
  // whole runs a little slower.
  bool timePasses = false;
};

// The passes of a frame, in the order they are drawn.
enum class RenderPass : int {
  ShadowNear,    // the nearest cascade's depth: terrain and trees
  ShadowMiddle,  // the middle cascade's
  ShadowFar,     // the farthest cascade's
  SkyAndTerrain,
  GroundCover,
  TreeMeshes,  // LOD0, LOD1 and LOD2
  Impostors,
};
inline constexpr int kRenderPassCount = 7;
static_assert(kShadowCascades == 3, "a shadow pass for each cascade");
// Their names in the benchmarks' output (bench/render_bench).
inline constexpr std::array<const char*, kRenderPassCount> kRenderPassNames{
    "shadow_near",  "shadow_middle", "shadow_far", "sky_and_terrain",
    "ground_cover", "tree_meshes",   "impostors"};

struct ForestStats {
  std::array<std::size_t, kLevelCount> instances{};  // per level, cross-fades counted twice
  std::size_t culled = 0;                            // outside the frustum
  std::size_t tooSmall = 0;                          // under the LOD settings' minimum size
  std::size_t lookedAt = 0;       // trees tested one by one (with a ForestIndex, not the too small)
  std::size_t triangles = 0;      // drawn in the colour pass
  std::size_t lod0Triangles = 0;  // the same trees all at LOD0, for comparison
  std::array<std::size_t, kLevelCount> shadowCasters{};  // per level it casts with
  // Impostor atlases baked for the types this frame was the first to draw as sprites, and
  // the levels it was the first to draw uploaded: the renderer's setup, not the frame's cost
  // (left out of FrameStats' times).
  double impostorBakeMs = 0.0;
  double meshUploadMs = 0.0;
  // The atlases this frame baked, and the ones it read from the cache instead
  // (ImpostorSettings::cacheFolder); sources sharing another's atlas are neither.
  std::size_t impostorAtlasesBaked = 0, impostorAtlasesCached = 0;
  double setupMs() const { return impostorBakeMs + meshUploadMs; }
  std::size_t shadowCasterCount() const {
    return std::accumulate(shadowCasters.begin(), shadowCasters.end(), std::size_t{0});
  }
};

struct FrameStats {
  ForestStats forest;
  std::size_t terrainTriangles = 0;
  std::size_t groundTufts = 0;  // grass and herb tufts drawn
  double prepareMs = 0.0;       // culling, LOD choice, instance upload (CPU)
  double frameMs = 0.0;         // the whole frame until the GPU finished
  // Each pass's time, where RenderOptions::timePasses asked for it (else zeros).
  std::array<double, kRenderPassCount> passMs{};
  // And the fragments each shaded, where the GL counts them (else zeros).
  std::array<std::size_t, kRenderPassCount> passFragments{};
  std::size_t triangles() const { return forest.triangles + terrainTriangles; }
};

}  // namespace eco
