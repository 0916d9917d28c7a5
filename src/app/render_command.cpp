#include "app/render_command.hpp"

#include <chrono>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/scene_source.hpp"
#include "core/error.hpp"
#include "render/gl_context.hpp"
#include "sim/image_io.hpp"

namespace eco {

std::optional<std::pair<int, int>> parseSize(const std::string& text) {
  int width = 0, height = 0;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &rest) != 3 || x != 'x')
    return std::nullopt;
  if (width < 16 || height < 16 || width > 8192 || height > 8192) return std::nullopt;
  return std::make_pair(width, height);
}

void addViewOptions(CLI::App& command, ViewOptions& o) {
  command.add_option(
      "--camera", o.camera,
      "Camera as X,Y,Z,YAW,PITCH: map east, north, altitude (m), bearing and pitch (degrees)");
  command.add_option("--view", o.view, "Camera preset when no --camera: overview, low or ground")
      ->check(CLI::IsMember({"overview", "low", "ground"}));
  command.add_option("--day", o.day, "Day of the year for the sun")->check(CLI::Range(1.0, 366.0));
  command.add_option("--hour", o.hour, "Solar time for the sun, hours")
      ->check(CLI::Range(0.0, 24.0));
  command.add_option("--wind-from", o.windFrom_deg,
                     "Wind bearing in degrees (default: the scenario's prevailing wind)");
  command.add_option("--wind-wg", o.windDirected, "Directed wind w_g (EcoMod)")
      ->check(CLI::Range(0.0, 10.0));
  command.add_option("--wind-ws", o.windSway, "Undirected wind w_s (EcoMod)")
      ->check(CLI::Range(0.0, 10.0));
  command.add_option("--wind-time", o.windTime, "Wind time t (radians of the sway)");
  command.add_option(
      "--overlay", o.overlay,
      "Colour the terrain by a map: a condition, suitability_<species> or canopy_height");
  command
      .add_option("--level", o.forceLevel, "Draw every tree at one level: 0-2 meshes, 3 impostors")
      ->check(CLI::Range(0, 3));
  command.add_flag("--no-impostors", o.noImpostors,
                   "LOD2 meshes all the way out instead of impostors");
  command.add_flag("--no-shadows", o.noShadows, "No shadow map");
}

Camera cameraFrom(const ViewOptions& o, const Terrain& terrain) {
  if (!o.camera.empty()) {
    std::optional<Camera> camera = parseCamera(o.camera);
    if (!camera)
      throw InputError(
          {"--camera", 0, ""},
          "expected five numbers X,Y,Z,YAW,PITCH with PITCH in -90..90, got '" + o.camera + "'");
    return *camera;
  }
  const CameraPreset preset = o.view == "ground" ? CameraPreset::Ground
                              : o.view == "low"  ? CameraPreset::Low
                                                 : CameraPreset::Overview;
  return presetCamera(preset, terrain);
}

RenderOptions renderOptionsFrom(const ViewOptions& o, const Scenario& scenario) {
  RenderOptions r;
  r.sun = {o.day, o.hour};
  r.wind.fromBearing_deg =
      o.windFrom_deg >= 0.0 ? o.windFrom_deg : scenario.climate.prevailingWindFrom_deg;
  r.wind.directed_wg = o.windDirected;
  r.wind.sway_ws = o.windSway;
  r.wind.time = o.windTime;
  r.lod.forcedLevel = o.forceLevel;
  r.lod.impostors = !o.noImpostors;
  r.shadows = !o.noShadows;
  return r;
}

namespace {

struct RenderArgs {
  std::string source;
  std::optional<int> year;
  std::string size = "1280x720";
  std::string out = "render.png";
  bool stats = false;
  std::size_t demoTrees = 0;
  ViewOptions view;
};

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

nlohmann::ordered_json statsJson(const FrameStats& s, double loadMs, double rendererMs) {
  const auto& n = s.forest.instances;
  return {{"renderer", glDescription()},
          {"instances", {{"lod0", n[0]}, {"lod1", n[1]}, {"lod2", n[2]}, {"impostor", n[3]}}},
          {"culled", s.forest.culled},
          {"too_small", s.forest.tooSmall},
          {"shadow_casters", s.forest.shadowCasters},
          {"triangles", s.triangles()},
          {"tree_triangles", s.forest.triangles},
          {"tree_triangles_all_lod0", s.forest.lod0Triangles},
          {"terrain_triangles", s.terrainTriangles},
          {"load_ms", loadMs},
          {"renderer_setup_ms", rendererMs},
          {"prepare_ms", s.prepareMs},
          {"frame_ms", s.frameMs}};
}

// Fails before the slow work when the output cannot be written.
void checkWritable(const std::filesystem::path& file) {
  requireOutputFolder(file);
  if (file.extension() != ".png")
    throw InputError({file.string(), 0, "--out"}, "the still must be a .png file");
}

void runRender(const RenderArgs& args) {
  const auto size = parseSize(args.size);
  if (!size)
    throw InputError({"--size", 0, ""},
                     "expected WIDTHxHEIGHT, each 16..8192, got '" + args.size + "'");
  const auto start = std::chrono::steady_clock::now();
  SceneSource source = openSceneSource(args.source);
  const int year = args.year.value_or(source.defaultYear());
  if (args.year && !source.run)
    throw InputError({"--year", 0, ""}, "a scenario has no years: render a run folder");
  source.requireSnapshot(year);
  checkWritable(args.out);
  std::optional<Field> overlay;
  if (!args.view.overlay.empty()) overlay = source.overlay(args.view.overlay);
  const Camera camera = cameraFrom(args.view, source.terrain);
  if (source.run || args.demoTrees > 0) source.buildLibrary();
  const Forest forest = source.forestOf(year, args.demoTrees);

  const double loadMs = millisecondsSince(start);

  const auto rendererStart = std::chrono::steady_clock::now();
  HeadlessGl gl;
  SceneRenderer renderer(source.terrain, source.scenario.climate.latitude_deg,
                         source.library.get());
  if (overlay) renderer.terrain().setOverlay(args.view.overlay, *overlay);
  RenderTarget target = RenderTarget::create(size->first, size->second);
  const double rendererMs = millisecondsSince(rendererStart);
  const FrameStats stats =
      renderer.render(&forest, camera, renderOptionsFrom(args.view, source.scenario), target);
  const Image image = readPixels(target.width, target.height);
  writeRgb8Image(args.out, image);
  if (args.stats) std::cout << statsJson(stats, loadMs, rendererMs).dump(2) << "\n";
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* command =
      app.add_subcommand("render", "Render one still of a run or a scenario, headless, into a PNG");
  command
      ->add_option("source", args->source,
                   "A run folder, or a scenario (name or .toml) for its terrain")
      ->required();
  command->add_option("--year", args->year, "Snapshot year of the run (default: its last)");
  command->add_option("--size", args->size, "Image size WIDTHxHEIGHT");
  command->add_option("--out", args->out, "PNG file to write");
  command->add_flag("--stats", args->stats,
                    "Print JSON: instances per level, triangles, frame milliseconds");
  command->add_option("--demo-trees", args->demoTrees,
                      "With a scenario: plant this many trees of its species at random");
  addViewOptions(*command, args->view);
  command->callback([args] { runRender(*args); });
}

}  // namespace eco
