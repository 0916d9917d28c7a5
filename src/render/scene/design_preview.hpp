// What the tree designer's preview shows (`ecoforest design`, docs/designer.md), without
// OpenGL: the edited tree at the level and age asked for, the sleeves of the visual hint
// over it, and beside it in a row to the east its other variants and ages and the compared
// species, all on a small flat patch under the same sun. The trees are built by a worker
// thread (PreviewBuilder) so that a large tree never stalls the window; the edited tree is
// published on its own first, the row after it.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "model/design/hint.hpp"
#include "render/scene/camera.hpp"
#include "render/scene/forest.hpp"
#include "render/scene/tree_library.hpp"

namespace eco {

struct PreviewSettings {
  std::uint64_t seed = 1;
  double age = 1.0;
  int level = 0;  // 0-2 the model's levels of detail, 3 (kLevelImpostor) the impostor
  std::optional<HintInterval> hint;
  bool operator==(const PreviewSettings&) const = default;
};

// The measures of the edited tree the designer shows.
struct PreviewStats {
  std::size_t segments = 0, leaves = 0, triangles = 0;
  double height_m = 0.0, crownRadius_m = 0.0;
  double buildMs = 0.0;  // skeletons and meshes (with the wind bases) of the edited tree
};

// The row beside the edited tree: these ages of its own seed, then these other seeds.
inline constexpr double kPreviewRowAges[] = {0.25, 0.5, 0.75};
inline constexpr int kPreviewRowVariants = 2;

// Library types of the preview, in this order: the edited tree, its hint sleeves, the row,
// one tree per compared species.
inline constexpr int kPreviewEdited = 0;
inline constexpr int kPreviewHint = 1;
inline constexpr int kPreviewRowFirst = 2;
inline constexpr int kPreviewComparedSpeciesFirst = 2;  // library species of the compared ones
int previewTypeCount(int comparedSpecies);

// Library species of the preview: the edited one, the hint's (the edited species in the hint
// colour), then the compared ones.
std::vector<Species> previewSpecies(const Species& edited, const std::vector<Species>& compared);
inline constexpr glm::vec3 kHintColor{1.0f, 0.42f, 0.05f};  // sRGB orange, unlike any bark

struct PreviewScene {
  std::uint64_t version = 0;  // of the designer's session it shows
  PreviewSettings settings;
  bool complete = false;         // false: only the edited tree and its hint (types 0 and 1)
  std::vector<TreeType> types;   // from type 0 on
  std::vector<glm::vec3> bases;  // world position of each type's tree, when complete
  PreviewStats stats;
};

// Builds the edited tree and its hint; addPreviewRow() then completes the scene with the
// row and the compared trees and places every tree.
PreviewScene buildPreview(const Species& edited, const PreviewSettings& settings);
void addPreviewRow(PreviewScene& scene, const Species& edited,
                   const std::vector<Species>& compared);
// Both at once on the calling thread (the headless designer, the window's first scene).
PreviewScene buildCompletePreview(const Species& edited, const std::vector<Species>& compared,
                                  const PreviewSettings& settings);

// The trees of a preview as a Forest, each type at its base as built: the edited tree, its
// hint sleeves when there is a hint, the row when asked for.
Forest previewForest(const std::vector<glm::vec3>& bases, bool hint, bool row);

// A flat patch of ground around the trees with room to spare.
Terrain previewGround(const std::vector<glm::vec3>& bases);

// The designer's camera: around `target` at `distance_m`, from compass bearing `yaw_deg`
// (looking toward the target) and `pitch_deg` above the horizon.
struct OrbitCamera {
  glm::vec3 target{0.0f, 5.0f, 0.0f};
  float distance_m = 25.0f;
  float yaw_deg = 0.0f;  // the view direction's bearing: 0 looks north
  float pitch_deg = 12.0f;
  Camera camera() const;
  // Turns by a pointer drag (degrees per pixel as the view's) and zooms by wheel steps.
  void orbit(float dx_px, float dy_px);
  void zoom(float steps);
};

// A worker thread that builds previews: the newest request wins, older ones are dropped.
class PreviewBuilder {
 public:
  explicit PreviewBuilder(std::vector<Species> compared);
  ~PreviewBuilder();
  PreviewBuilder(const PreviewBuilder&) = delete;
  PreviewBuilder& operator=(const PreviewBuilder&) = delete;

  void request(const Species& edited, std::uint64_t version, const PreviewSettings& settings);
  // The newest scene finished since the last call, if any; waits up to `wait` for one (the
  // beech is built within a frame, so the frame that asked can show it).
  std::optional<PreviewScene> take(std::chrono::milliseconds wait = {});
  bool busy() const;
  // How long the edited tree of the last request took: whether waiting for the next one is
  // worth a frame's time (0 before the first).
  double lastBuildMs() const;
  // What the window waits after a request: up to 12 ms when the tree builds in less than
  // that (a frame of 60 Hz holds it), nothing for a larger tree.
  std::chrono::milliseconds worthWaiting() const;

 private:
  struct Request {
    Species edited;
    std::uint64_t version;
    PreviewSettings settings;
  };
  void work();

  std::vector<Species> compared_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<Request> pending_;
  std::optional<PreviewScene> finished_;
  bool working_ = false;
  bool stopping_ = false;
  double lastBuildMs_ = 0.0;
  std::thread worker_;
};

}  // namespace eco
