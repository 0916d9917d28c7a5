// `ecoforest render`: one still of a run or a scenario, headless (EGL), written as PNG.
#pragma once

#include <optional>

#include <CLI/CLI.hpp>

#include "app/scene_source.hpp"
#include "app/view_options.hpp"
#include "core/image.hpp"
#include "render/gl/scene_renderer.hpp"

namespace eco {

void addRenderCommand(CLI::App& app);

// Draws a forest on its source's terrain (its library built) from a camera, headless, into
// an image of the options' size. `stats` gets the frame's figures, `setupMs` the renderer's
// setup time.
Image drawStill(const SceneSource& source, const Forest& forest, const Camera& camera,
                const ViewOptions& view, const std::optional<Field>& overlay,
                FrameStats* stats = nullptr, double* setupMs = nullptr);

}  // namespace eco
