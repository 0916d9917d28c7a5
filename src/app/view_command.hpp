// `ecoforest view`: a window to fly through a run (or a scenario's terrain), scrub through
// its years, change sun and wind, toggle species and see the LOD statistics.
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addViewCommand(CLI::App& app);

}  // namespace eco
