// One frame of a scene: sky, terrain and forest, lit by the sun with cascaded shadow maps
// out to a kilometre and more, fogged with distance, into a render target. `ecoforest render`,
// `view`, the tests and the benchmark all draw through this.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "render/gl/forest_renderer.hpp"
#include "render/gl/frame_uniforms.hpp"
#include "render/gl/gl_objects.hpp"
#include "render/gl/ground_cover_renderer.hpp"
#include "render/gl/shader.hpp"
#include "render/gl/terrain_renderer.hpp"
#include "render/scene/camera.hpp"
#include "render/scene/culling.hpp"
#include "render/scene/forest.hpp"
#include "render/scene/forest_floor.hpp"
#include "render/scene/impostor.hpp"
#include "render/scene/render_options.hpp"
#include "render/scene/sun.hpp"
#include "render/scene/timelapse.hpp"
#include "render/scene/tree_library.hpp"

namespace eco {

class SceneRenderer {
 public:
  // `library` may be null (terrain only); it and the terrain must outlive the renderer.
  SceneRenderer(const Terrain& terrain, double latitude_deg, const TreeLibrary* library,
                const ImpostorSettings& impostors = {});

  // `index`, where given, is the forest's own (ForestRenderer::prepare).
  FrameStats render(const Forest* forest, const Camera& camera, const RenderOptions& options,
                    const RenderTarget& target, const ForestIndex* index = nullptr);

  // Lays the forest floor under these trees (leaf litter where crowns cover the ground,
  // forest_floor.hpp, and the ground cover's light); kept until called again.
  void setForestFloor(const Forest& forest);
  // The same from a floor summed already (the crowns of a frame's trees, shown or not).
  void setForestFloor(const CanopyFloor& floor);
  // The ground's moisture on Ellenberg's F scale (sim's moistureOf), which the meadow's colour
  // and the ground cover follow; without it the ground is fresh everywhere.
  void setGroundMoisture(Field moisture);
  // The library's meshes changed (ForestRenderer::reloadMeshes).
  void reloadTrees(bool rebakeImpostors);

  TerrainRenderer& terrain() { return terrain_; }
  GroundCover& groundCover() { return groundCover_.cover(); }
  const Terrain& terrainData() const { return terrainData_; }
  ForestRenderer* forest() { return forest_.get(); }

 private:
  // Each cascade's depth map, a layer of shadowDepth_ (u: the frame's uniforms).
  void renderShadowMaps(const RenderOptions& options, FrameUniforms u,
                        const ShadowCascades& cascades, bool forestCasts,
                        const std::function<void(RenderPass)>& endPass);

  const Terrain& terrainData_;  // the caller's, as for the library
  double latitude_deg_;
  float hazeBase_m_;  // the altitude where the haze is as dense as the fog density says
  FrameUniformBuffer uniforms_;
  TerrainRenderer terrain_;
  GroundCoverRenderer groundCover_;
  std::unique_ptr<ForestRenderer> forest_;
  Program sky_;
  GlName skyArray_;
  GlName shadowFramebuffer_, shadowDepth_;
  int shadowSize_ = 0;
};

// The renderer as a time-lapse's back end: each call draws into one target of `size` (with
// `samples` a pixel) and reads the pixels back.
DrawFrame frameDrawer(SceneRenderer& renderer, FrameSize size, int samples = 1);

}  // namespace eco
