// `ecoforest timelapse`: growth or wind animations of a run as MP4 or PNG frames.
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addTimelapseCommand(CLI::App& app);

}  // namespace eco
