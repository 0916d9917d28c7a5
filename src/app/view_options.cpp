#include "app/view_options.hpp"

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "core/disk_cache.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "render/scene/tree_clearance.hpp"
#include "sim/conditions/moisture.hpp"

namespace eco {

void addSizeOption(CLI::App& command, FrameSize& size) {
  command
      .add_option_function<std::string>(
          "--size",
          [&size](const std::string& text) {
            const std::optional<FrameSize> parsed = parseFrameSize(text);
            if (!parsed)
              throw CLI::ValidationError(
                  "--size", "expected WIDTHxHEIGHT, each " + std::to_string(kMinFrameSide) + ".." +
                                std::to_string(kMaxFrameSide) + ", got '" + text + "'");
            size = *parsed;
          },
          "Frame size WIDTHxHEIGHT")
      ->default_str(toString(size));
}

void addFrameOptions(CLI::App& command, ViewOptions& o) {
  addSizeOption(command, o.size);
  command.add_option("--day", o.sun.dayOfYear, "Day of the year for the sun")
      ->check(CLI::Range(1.0, 366.0))
      ->capture_default_str();
  command.add_option("--hour", o.sun.solarHour, "Solar time for the sun, hours")
      ->check(CLI::Range(0.0, 24.0))
      ->capture_default_str();
  command
      .add_option("--wind-from", o.windFrom_deg,
                  "Wind bearing in degrees (default: the scenario's prevailing wind)")
      ->check(CLI::Range(0.0, 360.0));
  command.add_option("--wind-wg", o.windDirected_wg, "Directed wind w_g (EcoMod)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  command.add_option("--wind-ws", o.windSway_ws, "Undirected wind w_s (EcoMod)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  command
      .add_option_function<std::string>(
          "--quality",
          [&o](const std::string& text) {
            const std::optional<RenderQuality> parsed = parseRenderQuality(text);
            if (!parsed)
              throw CLI::ValidationError("--quality",
                                         "expected draft, balanced or high, got '" + text + "'");
            o.quality = *parsed;
          },
          "How much is drawn at full detail: draft, balanced or high")
      ->default_str(std::string(toString(o.quality)));
  command
      .add_option_function<std::string>(
          "--antialias",
          [&o](const std::string& text) {
            static const std::vector<std::string> counts{"1", "2", "4", "8", "16"};
            if (text == "auto")
              o.antialias = kAutoSamples;
            else if (std::find(counts.begin(), counts.end(), text) != counts.end())
              o.antialias = std::stoi(text);
            else
              throw CLI::ValidationError("--antialias",
                                         "expected auto, 1, 2, 4, 8 or 16, got '" + text + "'");
          },
          "Samples a pixel, multisample anti-aliasing: auto (4 on a GPU, none on a software "
          "rasteriser such as llvmpipe), 1 (none), 2, 4, 8 or 16 (as the OpenGL allows; "
          "llvmpipe 4)")
      ->default_str("auto");
  command
      .add_option("--level", o.forceLevel, "Draw every tree at one level: 0-2 meshes, 3 impostors")
      ->check(CLI::Range(0, 3));
  command.add_flag("--no-impostors", o.noImpostors,
                   "LOD2 meshes all the way out instead of impostors");
  command.add_flag("--no-shadows", o.noShadows, "No shadow map");
  command.add_flag("--no-shaping", o.noShaping,
                   "Draw a run's trees as their species' own, not shaped by light, wind and "
                   "crowding");
}

void addCameraOptions(CLI::App& command, ViewOptions& o) {
  command.add_option(
      "--camera", o.camera,
      "Camera as X,Y,Z,YAW,PITCH: map east, north, altitude (m), bearing and pitch (degrees)");
  command.add_option("--view", o.view, "Camera preset when no --camera: overview, low or ground")
      ->check(CLI::IsMember({"overview", "low", "ground"}))
      ->capture_default_str();
  command.add_option("--wind-time", o.windTime, "Wind time t (radians of the sway)");
  command.add_option(
      "--overlay", o.overlay,
      "Colour the terrain by a map: a condition, suitability_<species> or canopy_height");
}

void checkCameraOption(const ViewOptions& o) {
  if (!o.camera.empty() && !parseCamera(o.camera))
    throw InputError(
        {"--camera", 0, ""},
        "expected five numbers X,Y,Z,YAW,PITCH with PITCH in -90..90, got '" + o.camera + "'");
}

Camera cameraFrom(const ViewOptions& o, const Terrain& terrain, const Forest* trees,
                  const TreeLibrary* library) {
  checkCameraOption(o);
  if (!o.camera.empty()) return *parseCamera(o.camera);
  if (cameraNeedsTrees(o) && trees && library && trees->size() > 0)
    return groundCamera(terrain, *trees, *library);
  return presetCamera(o.view == "ground" ? CameraPreset::Ground
                      : o.view == "low"  ? CameraPreset::Low
                                         : CameraPreset::Overview,
                      terrain);
}

bool cameraNeedsTrees(const ViewOptions& o) {
  return o.camera.empty() && o.view == "ground";
}

RenderOptions renderOptionsFrom(const ViewOptions& o, const Scenario& scenario) {
  RenderOptions r;
  r.sun = o.sun;
  r.wind.fromBearing_deg = o.windFrom_deg.value_or(scenario.climate.prevailingWindFrom_deg);
  r.wind.directed_wg = o.windDirected_wg;
  r.wind.sway_ws = o.windSway_ws;
  r.wind.time = o.windTime;
  r.lod.switchPixels = switchPixelsFor(o.quality);
  r.lod.forcedLevel = o.forceLevel;
  r.lod.impostors = !o.noImpostors;
  r.shadows = !o.noShadows;
  r.groundCover = groundCoverFor(o.quality);
  return r;
}

std::unique_ptr<SceneRenderer> sceneRendererFor(const SceneSource& source, const ViewOptions& o) {
  ImpostorSettings impostors = impostorSettingsFor(o.quality);
  // Baked atlases are kept for the next command that draws the same trees (the valley's
  // take 17 s to bake, 1 s to read back).
  if (const std::optional<std::filesystem::path> cache = userCacheFolder())
    impostors.cacheFolder = *cache / "impostors";
  auto renderer = std::make_unique<SceneRenderer>(
      source.terrain, source.scenario.climate.latitude_deg, source.library.get(), impostors);
  // On a terminal the impostors' baking shows its progress: the valley's first frame waits
  // 15 s for it.
  if (renderer->forest() && Progress::stderrIsTerminal())
    renderer->forest()->onAtlasProgress(
        [line = std::shared_ptr<Progress>()](std::size_t done, std::size_t total) mutable {
          if (!line) line = std::make_shared<Progress>("impostor atlases", true);
          line->update(static_cast<double>(done) / static_cast<double>(total));
          if (done == total) line.reset();  // prints "done"
        });
  renderer->setGroundMoisture(
      moistureOf(source.terrain, source.scenario.climate.annualPrecipitation_mm));
  return renderer;
}

}  // namespace eco
