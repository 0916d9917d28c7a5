// `ecoforest stand`: a run's stand table, its trees of one year by diameter class and
// species (sim/run/stand_table.hpp, docs/validation.md "The stand table").
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addStandCommand(CLI::App& app);

}  // namespace eco
