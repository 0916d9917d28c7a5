// Scenario files (docs/scenario.md): where the landscape comes from and its climate.
// Paths are relative to the scenario file, except the output folder (relative to where
// ecoforest runs, like --out).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace eco {

struct GeneratedTerrain {
  int size = 513;           // cells per side; midpoint displacement needs 2^n + 1
  double roughness = 0.55;  // amplitude kept from one subdivision level to the next
  double relief_m = 600.0;  // height difference between the lowest and highest cell
};

struct TerrainSpec {
  std::optional<std::filesystem::path> heightmap;  // absolute after loading
  std::optional<GeneratedTerrain> generate;        // exactly one of the two
  double cellDx_m = 10.0;  // square 10 m cells unless the file says otherwise
  double cellDy_m = cellDx_m;
  std::optional<double> heightMin_m, heightMax_m;  // height_range_m
  double baseAltitude_m = 0.0;                     // generated terrain: height of its lowest cell
};

struct Climate {
  double latitude_deg = 46.0;
  double prevailingWindFrom_deg = 270.0;
  double annualPrecipitation_mm = 1100.0;
};

// How a plant's site suitability combines its five per-condition suitabilities.
enum class SuitabilityRule { Minimum, Product };

struct SimulationSettings {
  int years = 100;
  SuitabilityRule suitability = SuitabilityRule::Minimum;  // Liebig's law by default
  // Density caps, turned into plants per cell: stems of breast height and more (the canopy
  // layer) and plants below it (the regeneration layer, where seeds establish).
  double maxStemsPerHa = 1000.0;
  double maxSeedlingsPerHa = 500.0;
  int lightDirections = 16;  // sky directions of each plant's light estimate
  // A stem's light is traced every this many years (a different share of the stems each
  // year) and kept in between: a tree's light changes slowly, and tracing is most of a
  // year's work. Seedlings get their ground light every year; a new stem keeps its last
  // ground light until its turn.
  int lightRefreshYears = 2;
};

struct ScenarioSpecies {
  std::filesystem::path file;  // absolute after loading
  double seedRainPerHaPerYear = 0.0;
  SourceLocation where;  // the [[species]] entry, for errors about this species
};

struct OutputSettings {
  std::filesystem::path dir;  // relative to the working directory; default out/<name>
  int snapshotEveryYears = 10;
};

struct Scenario {
  std::filesystem::path file;
  std::string name;
  std::uint64_t seed = 1;
  TerrainSpec terrain;
  Climate climate;
  SimulationSettings simulation;
  std::vector<ScenarioSpecies> species;  // empty for terrain-only scenarios
  OutputSettings output;
};

Scenario loadScenario(const std::filesystem::path& file);

}  // namespace eco
