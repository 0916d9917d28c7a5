// `ecoforest export`: a run's forest of one year as one glTF file for other tools.
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addExportCommand(CLI::App& app);

}  // namespace eco
