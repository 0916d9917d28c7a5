#include "app/view_command.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "app/scene_source.hpp"
#include "app/view_options.hpp"
#include "app/view_panel.hpp"
#include "render/gl/window.hpp"
#include "render/scene/camera_controller.hpp"
#include "render/scene/forest_cache.hpp"
#include "render/scene/forest_index.hpp"
#include "render/scene/lod_budget.hpp"
#include "sim/image_io.hpp"

namespace eco {
namespace {

struct ViewArgs {
  std::string source;
  std::optional<int> year;
  std::size_t demoTrees = 0;
  int frames = 0;  // > 0: quit after this many frames (automation, tests)
  std::string screenshot = "ecoforest_view.png";
  double targetFps = 30.0;  // 0: the quality's switching sizes, fixed
  ViewOptions view;
};

// The trees of the shown year with the species the user switched off left out.
Forest visibleTrees(const Forest& all, const TreeLibrary& library, const std::vector<char>& shown) {
  Forest forest;
  forest.reserve(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!shown[library.type(all.type[i]).species]) continue;
    forest.append(all, i);
  }
  return forest;
}

void saveScreenshot(const RenderTarget& target, const std::string& file) {
  if (target.width == 0) return;  // nothing drawn yet
  writeRgb8Image(file, readPixels(target));
  std::cerr << "ecoforest view: saved " << file << "\n";
}

// The frame's size at a share of the window's width and height, at least a pixel.
FrameSize atResolution(FrameSize window, double resolution) {
  return {std::max(1, static_cast<int>(std::lround(window.width * resolution))),
          std::max(1, static_cast<int>(std::lround(window.height * resolution)))};
}

// The shadow maps' side at that share: their texels keep their size on the screen. In
// steps of 128 texels, so that small moves of the resolution do not reallocate them.
int shadowMapSizeAt(double resolution) {
  const double full = RenderOptions{}.shadowMapSize;
  return std::max(128, static_cast<int>(std::lround(full * resolution / 128.0)) * 128);
}

void runView(const ViewArgs& args) {
  SceneSource source = openSceneSource(args.source);
  if (args.year) source.requireSnapshot(*args.year);
  checkCameraOption(args.view);
  ViewState state;
  state.hasRun = source.run.has_value();
  state.years = source.run ? source.run->snapshotYears : std::vector<int>{};
  if (state.years.empty()) state.years.push_back(0);
  state.yearIndex = static_cast<int>(state.years.size()) - 1;
  if (args.year)
    state.yearIndex = static_cast<int>(
        std::find(state.years.begin(), state.years.end(), *args.year) - state.years.begin());
  std::optional<Field> overlay;
  if (!args.view.overlay.empty()) {
    overlay = source.overlay(args.view.overlay);
    state.overlayName = args.view.overlay;
    state.showOverlay = true;
  }
  if (source.run || args.demoTrees > 0)
    source.buildLibrary(LibrarySettings::shaped(source.run.has_value() && !args.view.noShaping));
  std::vector<std::string> speciesNames;
  if (source.library)
    for (const Species& s : source.library->species()) speciesNames.push_back(s.name);
  state.shown.assign(speciesNames.size(), 1);

  Window window("ecoforest — " + source.scenario.name, args.view.size, "`view`",
                "`ecoforest render` draws stills without one");
  const std::unique_ptr<SceneRenderer> renderer = sceneRendererFor(source, args.view);
  if (overlay) renderer->terrain().setOverlay(args.view.overlay, *overlay);
  RenderOptions options = renderOptionsFrom(args.view, source.scenario);
  std::optional<LodBudget> budget;
  if (args.targetFps > 0.0 && args.view.forceLevel < 0)
    budget.emplace(options.lod.switchPixels, 1000.0 / args.targetFps);
  ForestCache snapshots([&](int year) { return source.forestOf(year, args.demoTrees); },
                        defaultForestCacheBudget());
  // The shown year's forest itself, or a copy without the species switched off.
  const Forest none;
  Forest someSpecies;
  const Forest* forest = &none;
  // Its index, so that a frame looks only at the trees a pixel can show (ForestIndex).
  std::optional<ForestIndex> index;
  auto showForest = [&] {
    someSpecies = {};
    forest = &none;
    index.reset();
    if (!source.library) return;
    forest = &snapshots.of(state.years[state.yearIndex]);
    if (std::ranges::find(state.shown, 0) != state.shown.end()) {
      someSpecies = visibleTrees(*forest, *source.library, state.shown);
      forest = &someSpecies;
    }
    index.emplace(*forest, *source.library);
  };
  showForest();
  renderer->setForestFloor(*forest);
  CameraController controller(cameraFrom(args.view, source.terrain, forest, source.library.get()),
                              args.view.view == "ground");
  RenderTarget target;
  FrameStats stats;
  bool tookScreenshot = false;
  // A screenshot is the frame at the window's full resolution, drawn anew where the view
  // draws fewer pixels to hold its target.
  const auto saveFullScreenshot = [&](FrameSize size) {
    if (target.width == size.width && target.height == size.height) {
      saveScreenshot(target, args.screenshot);
    } else if (size.width > 0 && size.height > 0) {
      const RenderTarget full =
          RenderTarget::create(size.width, size.height, 0, args.view.antialias);
      RenderOptions fullOptions = options;
      fullOptions.shadowMapSize = RenderOptions{}.shadowMapSize;
      renderer->render(forest, controller.camera(), fullOptions, full, index ? &*index : nullptr);
      saveScreenshot(full, args.screenshot);
    }
    tookScreenshot = true;
  };
  double lastTime = window.seconds(), lastFrame_ms = 0.0;
  int shown = 0;
  for (int frame = 1; !window.shouldClose(); ++frame) {
    const ViewInput& input = window.beginFrame();
    const double now = window.seconds();
    lastFrame_ms = 1000.0 * (now - lastTime);
    // The first frames build the renderer's caches, and a frame that uploaded levels or baked
    // impostor atlases (types it was the first to draw so) measured setup, not drawing; one
    // that took a screenshot drew two frames.
    if (budget && frame > 2 && stats.forest.setupMs() == 0.0 && !tookScreenshot) {
      budget->update(lastFrame_ms);
      options.lod.switchPixels = budget->switchPixels();
      options.lod.minPixels = budget->minPixels();
      options.shadowMapSize = shadowMapSizeAt(budget->resolution());
    }
    tookScreenshot = false;
    // Capped so that a stall (a snapshot loading) does not fling the camera, but above the
    // frame time of llvmpipe at a few frames per second.
    const float dt = static_cast<float>(std::min(now - lastTime, 0.5));
    lastTime = now;
    controller.update(input, dt, source.terrain);
    bool screenshot = !input.keyboardTaken && input.presses(ViewKey::Screenshot) > 0;
    if (!input.keyboardTaken && input.presses(ViewKey::Play) % 2 == 1)
      state.playing = !state.playing;
    const bool yearStepped = state.advance(dt);
    options.wind.time += dt * 2.0;

    const PanelChanges changed =
        drawViewPanel(state, speciesNames, options, controller, stats, budget ? &*budget : nullptr);
    screenshot = screenshot || changed.screenshot;
    if (changed.overlay) {
      if (state.showOverlay)
        renderer->terrain().setOverlay(args.view.overlay, *overlay);
      else
        renderer->terrain().clearOverlay();
    }
    if (yearStepped || changed.year || changed.species) {
      showForest();
      renderer->setForestFloor(*forest);
    }

    const FrameSize size = window.framebufferSize();
    if (size.width > 0 && size.height > 0) {
      const FrameSize drawn = atResolution(size, budget ? budget->resolution() : 1.0);
      if (target.width != drawn.width || target.height != drawn.height)
        target = RenderTarget::create(drawn.width, drawn.height, 0, args.view.antialias);
      stats =
          renderer->render(forest, controller.camera(), options, target, index ? &*index : nullptr);
    }
    if (screenshot) saveFullScreenshot(size);
    window.present(target);
    ++shown;
    if (args.frames > 0 && frame >= args.frames) {
      if (!screenshot) saveFullScreenshot(size);
      break;
    }
  }
  // Where the frame rate ended up, for scripts that drive the view (--frames) and measure it.
  std::cerr << fmt::format("ecoforest view: {} frames, the last {:.0f} ms", shown, lastFrame_ms);
  if (budget)
    std::cerr << fmt::format(" (target {:.0f} ms{}): LOD sizes x{:.2f}, resolution {:.0f} %",
                             budget->target_ms(), budget->cannotReach() ? ", not reachable" : "",
                             budget->scale(), 100.0 * budget->resolution());
  std::cerr << "\n";
}

}  // namespace

void addViewCommand(CLI::App& app) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* command = app.add_subcommand("view",
                                         "Fly through a run or a scenario in a window (WASD, right "
                                         "mouse to look, G walk, P screenshot)");
  command->add_option("source", args->source, "A run folder, or a scenario (name or .toml)")
      ->required();
  command->add_option("--year", args->year,
                      "Snapshot year to start with (default: the run's last)");
  command->add_option("--demo-trees", args->demoTrees,
                      "With a scenario: plant this many trees at random");
  command->add_option("--frames", args->frames,
                      "Quit after this many frames, saving a screenshot (automation)");
  command->add_option("--screenshot", args->screenshot, "PNG file the screenshot key writes");
  command
      ->add_option("--target-fps", args->targetFps,
                   "Frame rate to hold by moving the levels of detail (0: the quality's fixed "
                   "switching sizes)")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  // The window starts from balanced and adapts; stills and time-lapses default to high.
  args->view.quality = RenderQuality::Balanced;
  addFrameOptions(*command, args->view);
  addCameraOptions(*command, args->view);
  command->callback([args] { runView(*args); });
}

}  // namespace eco
