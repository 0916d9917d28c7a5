// The panel of `ecoforest view` (Dear ImGui): the snapshot year and play button, species
// toggles, wind, sun, speed, LOD statistics and the frame-time target. It edits the view's state;
// the window and the camera are not its business.
#pragma once

#include <string>
#include <vector>

#include "render/gl/scene_renderer.hpp"
#include "render/scene/camera_controller.hpp"
#include "render/scene/lod_budget.hpp"

namespace eco {

// What the view shows besides the camera.
struct ViewState {
  std::vector<int> years;  // snapshot years ({0} for a scenario)
  int yearIndex = 0;
  bool playing = false;
  double playClock_s = 0.0;
  std::vector<char> shown;  // per species
  bool hasRun = false;
  std::string overlayName;  // empty: none to toggle
  bool showOverlay = false;

  // Steps the years once a second while playing; true when the year changed.
  bool advance(double dt_s);
};

struct PanelChanges {
  bool year = false, species = false, overlay = false, screenshot = false;
};

PanelChanges drawViewPanel(ViewState& state, const std::vector<std::string>& speciesNames,
                           RenderOptions& options, CameraController& controller,
                           const FrameStats& stats, const LodBudget* budget);

}  // namespace eco
