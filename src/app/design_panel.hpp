// The panels of `ecoforest design` (docs/designer.md), drawn with Dear ImGui over the
// preview: the global parameters of the paper's Fig. 1 as sliders with its bounds, the six
// pairs of local graphs of its Fig. 3 as poly-lines whose control points are dragged, added
// (click a segment) and removed (right-click a point), the combined value each pair gives
// the model, the preview's controls and the tree's statistics. Every edit goes through the
// DesignSession; the panel only reports what the user asked for.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "model/design/design_session.hpp"
#include "model/design/hint.hpp"
#include "render/scene/camera_controller.hpp"
#include "render/scene/design_preview.hpp"

namespace eco {

// A graph's point or segment held by the hint (the headless mode's [hint], or the user's
// hover); neither: the whole graph.
struct GraphFocus {
  LocalGraph graph = LocalGraph::KsG;
  int point = -1;
  int segment = -1;
};
HintInterval hintOf(const GraphFocus& focus, const Species& species);

struct DesignPanelState {
  PreviewSettings preview;
  bool row = true;                   // the variants, ages and compared species beside the tree
  bool windPlaying = true;           // the species' own sway (w_s, k_f)
  std::optional<GraphFocus> pinned;  // a hint that stays whatever the pointer does
  // Where each graph's control points were drawn last frame (window pixels): for the
  // layout report of the window test.
  std::vector<std::vector<glm::vec2>> pointPixels =
      std::vector<std::vector<glm::vec2>>(kLocalGraphCount);
  std::string status;                       // the last save or export, or what went wrong
  double windowFps = 0.0, previewMs = 0.0;  // how fast the window and its preview draw
  // The combined values of the six pairs over (g, w), computed once per species version.
  std::uint64_t combinedVersion = ~std::uint64_t{0};
  std::vector<std::vector<double>> combined;
  // The drag in progress.
  std::optional<GraphFocus> dragging;
  glm::vec2 grabOffset{0.0f};  // from the pointer to the point it grabbed, pixels
  std::uint64_t gesture = 0;
};

struct DesignPanelRequests {
  bool save = false, exportTree = false, screenshot = false;
  bool frameTree = false, frameRow = false;  // the camera buttons
  std::optional<HintInterval> hint;          // what the preview colours this frame
};

// Ctrl+Z undo, Ctrl+Y and Ctrl+Shift+Z redo, Ctrl+S save (into `requests`), from the
// window's key events.
void applyShortcuts(const std::vector<Shortcut>& shortcuts, DesignSession& session,
                    DesignPanelRequests& requests);

DesignPanelRequests drawDesignPanels(DesignSession& session, DesignPanelState& state,
                                     const PreviewStats& stats,
                                     const std::vector<std::string>& compared, glm::vec2 display);

}  // namespace eco
