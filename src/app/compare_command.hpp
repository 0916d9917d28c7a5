// `ecoforest compare`: runs side by side (docs/planning.md) — a table of their stand
// measures at chosen years, charts of the measures over time and stills from one camera.
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addCompareCommand(CLI::App& app);

}  // namespace eco
