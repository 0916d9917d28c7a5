// `ecoforest conditions`: the living-condition fields of a scenario's terrain, as maps.
// `ecoforest terrain`: a scenario's terrain saved as a heightmap.
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addConditionsCommand(CLI::App& app);
void addTerrainCommand(CLI::App& app);

}  // namespace eco
