// `ecoforest render`: one still of a run or a scenario, headless (EGL), written as PNG.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "render/camera.hpp"
#include "render/scene_renderer.hpp"

namespace eco {

void addRenderCommand(CLI::App& app);

// Options shared by `render`, `view` (and later `timelapse`): camera, light, wind, LOD.
struct ViewOptions {
  std::string camera;             // X,Y,Z,YAW,PITCH
  std::string view = "overview";  // overview | ground
  double day = 172.0, hour = 10.0;
  double windFrom_deg = -1.0;  // < 0: the scenario's prevailing wind
  double windDirected = 1.0, windSway = 1.0, windTime = 0.0;
  std::string overlay;
  int forceLevel = -1;
  bool noImpostors = false, noShadows = false;
};
void addViewOptions(CLI::App& command, ViewOptions& options);
// The camera the options ask for; an InputError names a malformed --camera.
Camera cameraFrom(const ViewOptions& options, const Terrain& terrain);
RenderOptions renderOptionsFrom(const ViewOptions& options, const Scenario& scenario);
// "1280x720" -> {1280, 720}; nullopt unless both are 16..8192.
std::optional<std::pair<int, int>> parseSize(const std::string& text);

}  // namespace eco
