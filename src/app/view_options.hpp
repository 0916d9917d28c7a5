// The options `render`, `view` and `timelapse` share — frame size, sun, wind, levels of
// detail, camera — declared once with their defaults, and turned into the renderer's
// settings in one place.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "app/scene_source.hpp"
#include "render/gl/gl_objects.hpp"
#include "render/gl/scene_renderer.hpp"
#include "render/scene/camera.hpp"
#include "render/scene/forest.hpp"
#include "render/scene/frame_size.hpp"
#include "sim/scenario.hpp"

namespace eco {

struct ViewOptions {
  FrameSize size;
  SunTime sun;
  std::optional<double> windFrom_deg;  // unset: the scenario's prevailing wind
  // The command line shows a light breeze unless told otherwise (the renderer's own default
  // is calm).
  double windDirected_wg = 1.0, windSway_ws = 1.0;
  double windTime = 0.0;
  // Stills and time-lapses are offline work and draw at high quality; `view` starts at
  // balanced and adapts to its frame-time target.
  RenderQuality quality = RenderQuality::High;
  int forceLevel = -1;  // -1: by size on screen
  bool noImpostors = false, noShadows = false;
  bool noShaping = false;  // a run's trees upright and open-grown, not shaped by their sites
  // Samples a pixel (multisample anti-aliasing): kAutoSamples by the OpenGL; 1 none.
  int antialias = kAutoSamples;
  // render and view only:
  std::string camera;             // X,Y,Z,YAW,PITCH
  std::string view = "overview";  // a camera preset
  std::string overlay;            // a map to colour the terrain with
};

// --size WIDTHxHEIGHT alone (the designer's window).
void addSizeOption(CLI::App& command, FrameSize& size);
// --size, --day, --hour, --wind-from, --wind-wg, --wind-ws, --quality, --antialias, --level,
// --no-impostors, --no-shadows, --no-shaping: what every command that draws frames takes.
void addFrameOptions(CLI::App& command, ViewOptions& options);
// --camera, --view, --wind-time, --overlay: the still and the window.
void addCameraOptions(CLI::App& command, ViewOptions& options);

// An InputError names a malformed --camera (before any slow work).
void checkCameraOption(const ViewOptions& options);
// The camera the options ask for. The ground preset among trees stands clear of them
// (groundCamera); without trees it stands at the map's centre.
Camera cameraFrom(const ViewOptions& options, const Terrain& terrain, const Forest* trees = nullptr,
                  const TreeLibrary* library = nullptr);
// Whether that camera is placed among the trees (the ground preset, no --camera).
bool cameraNeedsTrees(const ViewOptions& options);
RenderOptions renderOptionsFrom(const ViewOptions& options, const Scenario& scenario);
// The renderer of a scene at the options' quality (an OpenGL context current), its ground
// cover following the moisture the scenario's terrain and climate give.
std::unique_ptr<SceneRenderer> sceneRendererFor(const SceneSource& source,
                                                const ViewOptions& options);

}  // namespace eco
