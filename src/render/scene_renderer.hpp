// One frame of a scene: sky, terrain and forest, lit by the sun with a shadow map for the
// near field, fogged with distance, into a render target. `ecoforest render`, `view`, the
// tests and the benchmark all draw through this.
#pragma once

#include <memory>
#include <optional>

#include "render/camera.hpp"
#include "render/culling.hpp"
#include "render/forest.hpp"
#include "render/forest_renderer.hpp"
#include "render/frame_uniforms.hpp"
#include "render/gl_objects.hpp"
#include "render/impostor.hpp"
#include "render/shader.hpp"
#include "render/sun.hpp"
#include "render/terrain_renderer.hpp"
#include "render/tree_library.hpp"
#include "sim/scenario.hpp"

namespace eco {

struct SceneWind {
  // Where the wind comes from (0 north, 90 east): a scenario's prevailing wind.
  double fromBearing_deg = Climate{}.prevailingWindFrom_deg;
  double directed_wg = 0.0;        // w_g of the horizontal wind
  double sway_ws = 0.0;            // w_s of the undirected sway
  double gust = 0.25;              // relative swing of the directed wind over time
  double time = 0.0;               // t of the sway, radians
};

struct RenderOptions {
  SunTime sun;
  SceneWind wind;
  LodSettings lod;
  bool shadows = true;
  float shadowRange_m = 150.0f;  // half the side of the shadowed square ahead of the camera
  int shadowMapSize = 2048;
  std::optional<float> fogDensity;  // per metre; default clear air (100 km visibility)
};

struct FrameStats {
  ForestStats forest;
  std::size_t terrainTriangles = 0;
  double prepareMs = 0.0;  // culling, LOD choice, instance upload (CPU)
  double frameMs = 0.0;    // the whole frame until the GPU finished
  std::size_t triangles() const { return forest.triangles + terrainTriangles; }
};

class SceneRenderer {
 public:
  // `library` may be null (terrain only); it and the terrain must outlive the renderer.
  SceneRenderer(const Terrain& terrain, double latitude_deg, const TreeLibrary* library,
                const ImpostorSettings& impostors = {});

  FrameStats render(const Forest* forest, const Camera& camera, const RenderOptions& options,
                    const RenderTarget& target);

  TerrainRenderer& terrain() { return terrain_; }
  const Terrain& terrainData() const { return terrainData_; }
  ForestRenderer* forest() { return forest_.get(); }

 private:
  void renderShadowMap(const RenderOptions& options, const FrameUniforms& u, bool forestCasts);

  const Terrain& terrainData_;  // the caller's, as for the library
  double latitude_deg_;
  FrameUniformBuffer uniforms_;
  TerrainRenderer terrain_;
  std::unique_ptr<ForestRenderer> forest_;
  Program sky_;
  GlName skyArray_;
  GlName shadowFramebuffer_, shadowDepth_;
  int shadowSize_ = 0;
};

}  // namespace eco
