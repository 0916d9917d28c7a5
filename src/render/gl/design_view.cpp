#include "render/gl/design_view.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace eco {

DesignView::DesignView(const Species& edited, const std::vector<Species>& compared,
                       PreviewScene first) {
  ECO_ASSERT(first.complete, "the first preview must place every tree");
  bases_ = first.bases;
  ground_ = previewGround(bases_);
  library_ =
      std::make_unique<TreeLibrary>(previewSpecies(edited, compared), std::move(first.types));
  renderer_ = std::make_unique<SceneRenderer>(ground_, kPreviewLatitude_deg, library_.get());
  first.types.clear();
  shown_ = std::move(first);
}

void DesignView::show(PreviewScene scene) {
  for (std::size_t t = 0; t < scene.types.size(); ++t)
    library_->setType(static_cast<int>(t), std::move(scene.types[t]));
  if (scene.complete) bases_ = scene.bases;
  renderer_->reloadTrees(scene.settings.level == kLevelImpostor);
  scene.types.clear();
  shown_ = std::move(scene);
}

OrbitCamera DesignView::framingCamera() const {
  const TreeType& tree = library_->type(kPreviewEdited);
  OrbitCamera camera;
  camera.target = bases_[kPreviewEdited] + glm::vec3(0.0f, 0.5f * tree.height_m, 0.0f);
  camera.distance_m = 1.5f * std::max(tree.height_m, 2.0f * tree.crownRadius_m) + 3.0f;
  return camera;
}

OrbitCamera DesignView::rowCamera() const {
  float west = bases_.front().x, east = west, tallest = 0.0f;
  for (std::size_t t = 0; t < bases_.size(); ++t) {
    const TreeType& type = library_->type(static_cast<int>(t));
    west = std::min(west, bases_[t].x - type.crownRadius_m);
    east = std::max(east, bases_[t].x + type.crownRadius_m);
    tallest = std::max(tallest, type.height_m);
  }
  OrbitCamera camera;
  camera.target = glm::vec3(0.5f * (west + east), 0.45f * tallest, bases_.front().z);
  // The row's width fills about two thirds of a 50-degree wide view.
  camera.distance_m = std::max(0.8f * (east - west), 1.5f * tallest);
  camera.pitch_deg = 10.0f;
  return camera;
}

FrameStats DesignView::render(const OrbitCamera& camera, const RenderOptions& options, bool row,
                              const RenderTarget& target) {
  const Forest forest = previewForest(bases_, shown_.settings.hint.has_value(), row);
  return renderer_->render(&forest, camera.camera(), options, target);
}

RenderOptions previewRenderOptions(const PreviewSettings& settings, double sway_ws,
                                   double windTime) {
  RenderOptions options;
  options.lod.forcedLevel = settings.level;
  options.shadowReach = {20.0f, 60.0f};  // the tree and its row, a few tens of metres away
  options.wind.sway_ws = sway_ws;
  options.wind.time = windTime;
  return options;
}

}  // namespace eco
