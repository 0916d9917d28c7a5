// `ecoforest conditions`: the living-condition fields of a scenario's terrain, as maps.
// `ecoforest terrain`: a scenario's terrain saved as a heightmap.
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addConditionsCommand(CLI::App& app);
void addTerrainCommand(CLI::App& app);

// --ignore-memory-check, for the commands that compute the living conditions (conditions,
// run): go ahead where requireMemoryForConditions would refuse the terrain.
void addIgnoreMemoryCheckFlag(CLI::App& command, bool& ignore);

}  // namespace eco
