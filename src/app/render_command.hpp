// `ecoforest render`: one still of a run or a scenario, headless (EGL), written as PNG.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "app/scene_source.hpp"
#include "app/view_options.hpp"
#include "core/image.hpp"
#include "render/gl/scene_renderer.hpp"

namespace eco {

void addRenderCommand(CLI::App& app);

// What drawing a still measured: the frame's figures, the renderer's setup time and the
// OpenGL renderer's name (asked while its context lives).
struct StillStats {
  FrameStats frame;
  double setupMs = 0.0;
  std::string renderer;
  ForestGpuMemory treeMemory;  // the library's meshes and impostors on the GPU
  int samples = 1;             // a pixel, as drawn (--antialias auto resolved)
};

// Draws a forest on its source's terrain (its library built) from a camera, headless, into
// an image of the options' size: the trees shown on the floor of all of them, the trees
// left out counted with those the renderer does not draw.
Image drawStill(const SceneSource& source, const SeenForest& trees, const Camera& camera,
                const ViewOptions& view, const std::optional<Field>& overlay,
                StillStats* stats = nullptr);
// The trees a still of `view` from `camera` draws out of the source's year (or its demo
// planting): SceneSource::forestSeenFrom with the view's size and levels.
SeenForest stillTrees(const SceneSource& source, int year, std::size_t demoTrees,
                      const Camera& camera, const ViewOptions& view);

}  // namespace eco
