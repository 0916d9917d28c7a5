#include "app/render_command.hpp"

#include <chrono>
#include <iostream>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/scene_source.hpp"
#include "app/view_options.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "render/gl/gl_context.hpp"
#include "render/scene/forest_index.hpp"
#include "sim/image_io.hpp"

namespace eco {

namespace {

struct RenderArgs {
  std::string source;
  std::optional<int> year;
  std::string out = "render.png";
  bool stats = false;
  std::size_t demoTrees = 0;
  ViewOptions view;
};

double mebibytes(std::size_t bytes) {
  return static_cast<double>(bytes) / (1024.0 * 1024.0);
}

nlohmann::ordered_json statsJson(const StillStats& still, double loadMs) {
  const FrameStats& s = still.frame;
  const auto& n = s.forest.instances;
  return {
      {"renderer", still.renderer},
      {"antialias_samples", still.samples},
      {"instances", {{"lod0", n[0]}, {"lod1", n[1]}, {"lod2", n[2]}, {"impostor", n[3]}}},
      {"culled", s.forest.culled},
      {"too_small", s.forest.tooSmall},
      {"trees_looked_at", s.forest.lookedAt},
      {"shadow_casters", s.forest.shadowCasterCount()},
      {"triangles", s.triangles()},
      {"tree_triangles", s.forest.triangles},
      {"tree_triangles_all_lod0", s.forest.lod0Triangles},
      {"terrain_triangles", s.terrainTriangles},
      {"ground_tufts", s.groundTufts},
      {"tree_gpu_mib",
       {{"meshes", mebibytes(still.treeMemory.meshBytes)},
        {"impostors", mebibytes(still.treeMemory.impostorBytes)}}},
      {"load_ms", loadMs},
      {"renderer_setup_ms", still.setupMs},
      {"mesh_upload_ms", s.forest.meshUploadMs},
      {"impostor_bake_ms", s.forest.impostorBakeMs},
      {"impostor_atlases",
       {{"baked", s.forest.impostorAtlasesBaked}, {"from_cache", s.forest.impostorAtlasesCached}}},
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
  const auto start = std::chrono::steady_clock::now();
  SceneSource source = openSceneSource(args.source);
  const int year = args.year.value_or(source.defaultYear());
  if (args.year && !source.run)
    throw InputError({"--year", 0, ""}, "a scenario has no years: render a run folder");
  source.requireSnapshot(year);
  checkWritable(args.out);
  std::optional<Field> overlay;
  if (!args.view.overlay.empty()) overlay = source.overlay(args.view.overlay);
  checkCameraOption(args.view);
  // On a terminal each slow step says what it does (a still of a whole run takes minutes
  // at high quality on a software renderer); logs and tests stay clean.
  const bool terminal = Progress::stderrIsTerminal();
  if (terminal && source.run) std::cerr << fmt::format("render: reading year {}\n", year);
  if (source.run || args.demoTrees > 0)
    source.buildLibrary(LibrarySettings::shaped(source.run.has_value() && !args.view.noShaping));
  // The ground preset stands where the trees leave room, so it places its camera among the
  // trees near the map's centre, read first; any other camera is placed by the terrain alone.
  // The still then holds only the trees it can show (a landscape's year, a hundred million
  // plants, holds a few million).
  Camera camera;
  if (cameraNeedsTrees(args.view)) {
    const Forest nearCentre = source.forestForGroundCamera(year, args.demoTrees);
    camera = cameraFrom(args.view, source.terrain, &nearCentre, source.library.get());
  } else {
    camera = cameraFrom(args.view, source.terrain);
  }
  const SeenForest trees = stillTrees(source, year, args.demoTrees, camera, args.view);

  const double loadMs = millisecondsSince(start);
  StillStats stats;
  if (terminal)
    std::cerr << fmt::format("render: drawing {} of {} plants, {}x{} at {} quality\n",
                             trees.shown.size(), trees.shown.size() + trees.culled + trees.tooSmall,
                             args.view.size.width, args.view.size.height,
                             toString(args.view.quality));
  const Image image = drawStill(source, trees, camera, args.view, overlay, &stats);
  writeRgb8Image(args.out, image);
  if (terminal)
    std::cerr << fmt::format("render: wrote {} in {:.1f} s\n", args.out,
                             millisecondsSince(start) / 1000.0);
  if (args.stats) std::cout << statsJson(stats, loadMs).dump(2) << "\n";
}

}  // namespace

Image drawStill(const SceneSource& source, const SeenForest& trees, const Camera& camera,
                const ViewOptions& view, const std::optional<Field>& overlay, StillStats* stats) {
  const auto rendererStart = std::chrono::steady_clock::now();
  HeadlessGl gl;
  const std::unique_ptr<SceneRenderer> renderer = sceneRendererFor(source, view);
  if (overlay) renderer->terrain().setOverlay(view.overlay, *overlay);
  renderer->setForestFloor(trees.floor);
  // A frame looks only at the trees a pixel can show (ForestIndex): most of a whole forest.
  std::optional<ForestIndex> index;
  if (source.library) index.emplace(trees.shown, *source.library);
  RenderTarget target = RenderTarget::create(view.size.width, view.size.height, 0, view.antialias);
  const double setupMs = millisecondsSince(rendererStart);
  FrameStats frame =
      renderer->render(&trees.shown, camera, renderOptionsFrom(view, source.scenario), target,
                       index ? &*index : nullptr);
  frame.forest.culled += trees.culled;
  frame.forest.tooSmall += trees.tooSmall;
  if (stats)
    *stats = {frame, setupMs, glDescription(),
              renderer->forest() ? renderer->forest()->gpuMemory() : ForestGpuMemory{},
              target.samples};
  return readPixels(target);
}

SeenForest stillTrees(const SceneSource& source, int year, std::size_t demoTrees,
                      const Camera& camera, const ViewOptions& view) {
  return source.forestSeenFrom(year, demoTrees, camera, view.size,
                               renderOptionsFrom(view, source.scenario).lod);
}

void addRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* command =
      app.add_subcommand("render", "Render one still of a run or a scenario, headless, into a PNG");
  command
      ->add_option("source", args->source,
                   "A run folder, or a scenario (name or .toml) for its terrain")
      ->required();
  command->add_option("--year", args->year, "Snapshot year of the run (default: its last)");
  command->add_option("--out", args->out, "PNG file to write");
  command->add_flag("--stats", args->stats,
                    "Print JSON: instances per level, triangles, frame milliseconds");
  command->add_option("--demo-trees", args->demoTrees,
                      "With a scenario: plant this many trees of its species at random");
  addFrameOptions(*command, args->view);
  addCameraOptions(*command, args->view);
  command->callback([args] { runRender(*args); });
}

}  // namespace eco
