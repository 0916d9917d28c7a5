// The designer's 3D preview on the GPU: the patch of ground, the preview's tree library
// (design_preview.hpp) and the scene renderer that draws it, shown from the orbit camera.
// A newer PreviewScene replaces the trees it holds without rebuilding the renderer, whose
// materials and shaders stay.
#pragma once

#include <memory>
#include <vector>

#include "render/gl/scene_renderer.hpp"
#include "render/scene/design_preview.hpp"

namespace eco {

class DesignView {
 public:
  // `first` must be complete (addPreviewRow): it places the trees and sizes the ground.
  DesignView(const Species& edited, const std::vector<Species>& compared, PreviewScene first);

  void show(PreviewScene scene);
  const PreviewScene& shown() const { return shown_; }
  // The orbit camera that frames the edited tree (of the first scene), or the whole row.
  OrbitCamera framingCamera() const;
  OrbitCamera rowCamera() const;

  FrameStats render(const OrbitCamera& camera, const RenderOptions& options, bool row,
                    const RenderTarget& target);

 private:
  PreviewScene shown_;  // its types moved into the library; settings, bases and stats kept
  std::vector<glm::vec3> bases_;
  Terrain ground_;
  std::unique_ptr<TreeLibrary> library_;
  std::unique_ptr<SceneRenderer> renderer_;
};

// The sun, sky and wind of the preview: a June morning at 46 degrees north (the paper's
// Slovenia), the edited species' own sway w_s (0 while the wind is paused) at `windTime`,
// the level the designer shows.
RenderOptions previewRenderOptions(const PreviewSettings& settings, double sway_ws,
                                   double windTime);
inline constexpr double kPreviewLatitude_deg = 46.0;

}  // namespace eco
