// What a run writes besides maps (docs/simulation.md): yearly statistics per species, tree
// lists at snapshots, and the canopy height map.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "sim/ecosystem.hpp"

namespace eco {

// One line of stats.csv. Plain numbers without padding so that checkpoints can hold rows.
struct StatsRow {
  std::int32_t year = 0;
  std::int32_t species = 0;
  std::int64_t alive = 0, born = 0, died = 0;
  double meanHeight_m = 0.0;
  double basalArea_m2PerHa = 0.0;  // stem cross-sections at breast height per hectare
  double coverFraction = 0.0;      // share of cell centres under a crown of the species
};

// The rows of the year just stepped, one per species.
std::vector<StatsRow> statsOfYear(const Ecosystem& ecosystem);

void writeStatsCsv(const std::filesystem::path& file, const std::vector<StatsRow>& rows,
                   const std::vector<EcosystemSpecies>& species);
void writeTreesCsv(const std::filesystem::path& file, const Ecosystem& ecosystem);

// The height of the tallest plant whose crown covers each cell centre, 0 where none does.
Field canopyHeight(const Ecosystem& ecosystem);

}  // namespace eco
