// `ecoforest run`: the afforestation simulation of a scenario into a run folder.
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addRunCommand(CLI::App& app);

}  // namespace eco
