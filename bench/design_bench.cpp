// How immediate the designer's preview is (issue: "the beech rebuilds and redraws within one
// frame, under 16 ms for skeleton and mesh; for the pine the rebuild runs off the UI thread
// and the window keeps at least 30 frames per second on llvmpipe while a point is dragged").
// Prints, for the paper's beech and pine:
//   rebuild   the edited tree's skeleton and LOD0 mesh as the preview builds it (median);
//   frame     one preview picture (sky, ground, the tree and its row, shadows) at SIZE;
//   window    the window thread's frames per second while a control point moves every
//             frame: the designer's panels (design_panel.hpp), the wait for a quick tree, the tree
//             rebuilt on the builder's thread and drawn on the preview's (background_preview.hpp),
//             the newest picture uploaded; and how many new pictures (with a newer tree) came back
//             meanwhile. The loop waits for a 60 Hz refresh as the window's swap does.
// Usage: design_bench [SIZE = 1280x720] [FRAMES = 60]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <imgui.h>

#include "app/design_panel.hpp"
#include "core/stopwatch.hpp"
#include "model/design/design_session.hpp"
#include "model/species.hpp"
#include "render/gl/background_preview.hpp"
#include "render/gl/design_view.hpp"
#include "render/gl/gl_context.hpp"
#include "render/gl/offscreen_ui.hpp"

namespace {

using Clock = std::chrono::steady_clock;

using eco::millisecondsSince;

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const eco::FrameSize size =
      argc > 1 ? eco::parseFrameSize(argv[1]).value_or(eco::FrameSize{}) : eco::FrameSize{};
  const int frames = argc > 2 ? std::max(3, std::stoi(argv[2])) : 60;
  eco::HeadlessGl gl;
  std::printf("design preview on %s at %dx%d\n", eco::glDescription().c_str(), size.width,
              size.height);
  std::setvbuf(stdout, nullptr, _IONBF, 0);
  std::printf("%-6s %11s %10s %12s %16s\n", "tree", "rebuild ms", "frame ms", "window fps",
              "new pictures");
  // The pictures of each tree first, on this thread; then the window's loop, whose
  // pictures come from the preview's own thread and context.
  std::vector<eco::Species> trees;
  for (const char* name : {"beech", "pine"})
    trees.push_back(
        eco::loadSpecies(std::string(ECOFOREST_DATA_DIR) + "/species/" + name + ".toml"));
  const eco::PreviewSettings settings;
  std::vector<double> rebuildMs, frameMs;
  for (const eco::Species& species : trees) {
    std::vector<double> rebuild;
    for (int i = 0; i < 5; ++i) {
      const auto start = Clock::now();
      (void)eco::buildPreview(species, settings);
      rebuild.push_back(millisecondsSince(start));
    }
    rebuildMs.push_back(median(rebuild));
    eco::DesignView view(species, {}, eco::buildCompletePreview(species, {}, settings));
    const eco::RenderTarget target = eco::RenderTarget::create(size.width, size.height);
    const eco::RenderOptions options = eco::previewRenderOptions(settings, 0.0, 0.0);
    std::vector<double> ms;
    for (int i = 0; i < 5; ++i)
      ms.push_back(view.render(view.framingCamera(), options, true, target).frameMs);
    frameMs.push_back(median(ms));
  }

  eco::OffscreenUi ui;
  for (std::size_t t = 0; t < trees.size(); ++t) {
    const eco::Species& species = trees[t];
    eco::DesignSession session(species);
    eco::PreviewBuilder builder({});
    eco::BackgroundPreview preview(species, {}, eco::buildCompletePreview(species, {}, settings));
    const eco::PreviewFrame asked{preview.framingCamera(), true, 0.0, 0.0, size};
    eco::RenderTarget shown = eco::RenderTarget::create(size.width, size.height);
    eco::DesignPanelState state;
    eco::PreviewStats stats;
    int pictures = 0;
    const auto start = Clock::now();
    for (int f = 0; f < frames; ++f) {
      const auto frameStart = Clock::now();
      ui.beginFrame(size);
      drawDesignPanels(session, state, stats, {},
                       {static_cast<float>(size.width), static_cast<float>(size.height)});
      session.apply(eco::MovePoint{eco::LocalGraph::MinLenG, 1, 7.5, 0.45 + 0.3 * f / frames}, 1);
      builder.request(session.species(), session.version(), settings);
      std::optional<eco::PreviewScene> scene = builder.take(builder.worthWaiting());
      if (scene) preview.request(asked, std::move(scene));
      if (std::optional<eco::RenderedPreview> picture = preview.take()) {
        eco::writePixels(shown, picture->image);
        stats = picture->stats;
        ++pictures;
      }
      ui.drawOnto(shown);
      glFinish();
      // The window waits for the display's refresh (swap interval 1): at most 60 frames a
      // second, the rest of the time left to the builder and the preview.
      std::this_thread::sleep_until(frameStart + std::chrono::microseconds(16667));
    }
    const double fps = 1000.0 * frames / millisecondsSince(start);
    std::printf("%-6s %11.1f %10.1f %12.1f %9d in %d frames\n", species.name.c_str(), rebuildMs[t],
                frameMs[t], fps, pictures, frames);
  }
  return 0;
}
