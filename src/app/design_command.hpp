// `ecoforest design`: the EcoMod tree designer (docs/designer.md) — a window with the
// paper's dialogs and an immediate 3D preview, or, with --apply, a headless run of a file of
// edits that saves, exports and screenshots the result.
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addDesignCommand(CLI::App& app);

}  // namespace eco
