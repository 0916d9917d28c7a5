// What a run measures (docs/run_folder.md): yearly statistics per species (stats.csv,
// written by run_format.hpp) and the canopy height map.
#pragma once

#include <vector>

#include "sim/ecology/ecosystem.hpp"
#include "sim/plan/management.hpp"
#include "sim/run/run_format.hpp"

namespace eco {

// The rows of the year just stepped, with what the plan did in it: one per species, then
// the whole stand's.
std::vector<StatsRow> statsOfYear(const Ecosystem& ecosystem, const PlanYear& plan);

// The height of the tallest plant whose crown covers each cell centre, 0 where none does.
Field canopyHeight(const Ecosystem& ecosystem);

}  // namespace eco
