// `ecoforest render`: one still of a run or a scenario, headless (EGL), written as PNG.
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addRenderCommand(CLI::App& app);

}  // namespace eco
