// Time-lapses of a run (docs/rendering.md): growth, the forest growing continuously from
// year to year between its snapshots; or wind, one year with the wind's time advancing. Each
// frame is drawn by the back end it is given (the OpenGL scene renderer, headless),
// optionally overlaid with the year and a scale bar, and handed to a FrameSink (PNG frames or
// MP4).
#pragma once

#include <functional>

#include "render/scene/camera_path.hpp"
#include "render/scene/forest.hpp"
#include "render/scene/forest_floor.hpp"
#include "render/scene/forest_index.hpp"
#include "render/scene/frame_sink.hpp"
#include "render/scene/frame_size.hpp"
#include "render/scene/render_options.hpp"
#include "render/scene/tree_library.hpp"
#include "sim/run/run_folder.hpp"

namespace eco {

enum class TimelapseKind { Growth, Wind };

struct TimelapseSettings {
  TimelapseKind kind = TimelapseKind::Growth;
  double fromYear = 0.0;  // growth: 0 starts from the bare landscape; wind: the year shown
  double toYear = 0.0;
  double seconds = 10.0;
  int fps = 30;
  FrameSize frame;
  CameraPath camera;
  RenderOptions render;  // wind.time is advanced by the wind kind
  bool overlay = false;  // year counter and scale bar
  // Growth: pair two snapshots' trees even where they seem not to fit in the memory
  // available (GrowthInterval::peakBytes), instead of refusing before the pairing.
  bool ignoreMemoryCheck = false;
  double windRadiansPerSecond = 2.0;

  int frameCount() const;
  double yearOfFrame(int frame) const;
};

struct TimelapseTimings {
  int frames = 0;
  double instances_s = 0.0;  // reading snapshots, interpolating, the forest arrays and floor
  double render_s = 0.0;     // culling, drawing and reading pixels back
  double encode_s = 0.0;     // overlay and handing frames to the sink (PNG or ffmpeg)
  double total_s = 0.0;
};

// A frame's trees: those the renderer may draw from the frame's camera (a landscape's
// frame leaves out the millions under a pixel, LodSettings::minPixels), and the floor of
// every tree of the frame, which shows the crowns of those left out.
struct FrameTrees {
  const Forest& shown;
  const CanopyFloor& floor;
  // The shown trees indexed (ForestIndex), where the same trees are drawn in every frame (a
  // wind time-lapse): each frame then looks only at those a pixel can show.
  const ForestIndex* index = nullptr;
};

// Draws one frame of the terrain and its trees and reads it back.
using DrawFrame = std::function<Image(const FrameTrees& trees, const Camera& camera,
                                      const RenderOptions& options)>;

// `progress(frame done, frames)` after each frame. `terrain` is the run's, for the scale bar.
TimelapseTimings renderTimelapse(const RunFolder& run, const TreeLibrary& library,
                                 const Terrain& terrain, const DrawFrame& draw,
                                 const TimelapseSettings& settings, FrameSink& sink,
                                 const std::function<void(int, int)>& progress);

// Draws the year (top left) and a scale bar for the view's centre (bottom left) into `frame`.
void drawOverlay(Image& frame, double year, double metresPerPixel);
// Metres per pixel where the centre of the view meets the ground (or 1 km ahead).
double metresPerPixelAtCentre(const Camera& camera, const Terrain& terrain, int height);

}  // namespace eco
