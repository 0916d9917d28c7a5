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
#include "sim/plan/plan_spec.hpp"

namespace eco {

struct GeneratedTerrain {
  int size = 513;           // cells per side; midpoint displacement needs 2^n + 1
  double roughness = 0.55;  // amplitude kept from one subdivision level to the next
  double relief_m = 600.0;  // height difference between the lowest and highest cell
};

// What the closed depressions of a heightmap (pits with no way out at the surface) are
// (docs/conditions.md, "Moisture"): drained, as karst sinks and the artefacts of generated
// or measured heightmaps are, or ponds that hold water to their spill level.
enum class ClosedDepressions { Drain, Pond };

struct TerrainSpec {
  std::optional<std::filesystem::path> heightmap;  // absolute after loading
  std::optional<GeneratedTerrain> generate;        // exactly one of the two
  double cellDx_m = 10.0;  // square 10 m cells unless the file says otherwise
  double cellDy_m = cellDx_m;
  std::optional<SourceLocation> cellSizeAt;        // where cell_size_m was given, if it was
  std::optional<double> heightMin_m, heightMax_m;  // height_range_m
  double baseAltitude_m = 0.0;                     // generated terrain: height of its lowest cell
  ClosedDepressions closedDepressions = ClosedDepressions::Drain;
};

struct Climate {
  double latitude_deg = 46.0;
  double prevailingWindFrom_deg = 270.0;
  double annualPrecipitation_mm = 1100.0;
  // Mean annual air temperature at a reference altitude, and how it falls with height
  // (the standard atmosphere's 6.5 K per km): altitude acts on species through it.
  double meanAnnualTemperature_c = 9.5;
  double temperatureAltitude_m = 300.0;
  double lapseRate_K_per_m = 0.0065;
  // The mean annual temperature at an altitude.
  double temperatureAt(double altitude_m) const {
    return meanAnnualTemperature_c - lapseRate_K_per_m * (altitude_m - temperatureAltitude_m);
  }
};

// How a plant's site suitability combines its five per-condition suitabilities.
enum class SuitabilityRule { Minimum, Product };

struct SimulationSettings {
  int years = 100;
  SuitabilityRule suitability = SuitabilityRule::Minimum;  // Liebig's law by default
};

// A [validation] table: the yield table a planted pure stand of the scenario should follow
// (`ecoforest validate`, docs/validation.md).
struct ValidationSettings {
  std::filesystem::path yieldTable;  // relative to the scenario file
  std::string species;               // the planted species measured
  std::vector<int> checkedAges;      // ages compared; empty: every age of the table
  double tolerance = 0.15;           // largest relative difference accepted
  // The stand's self-thinning line, ln N over ln qmd, fitted over these years, and the
  // slopes accepted (Reineke's is -1.605).
  int thinningFrom_years = 60, thinningTo_years = 120;
  double steepestThinningSlope = -2.0, shallowestThinningSlope = -1.3;
  SourceLocation where;
};

struct ScenarioSpecies {
  std::filesystem::path file;  // absolute after loading
  double seedRainPerHaPerYear = 0.0;
  double surroundingForestShare = 0.0;  // of the forest around the map (its seed source)
  SourceLocation where;                 // the [[species]] entry, for errors about this species
};

// How tree snapshots are written (sim/run/trees_file.hpp): CSV for any tool, or binary
// records, fewer bytes and no numbers to format, for landscapes of millions of plants.
enum class SnapshotFormat { Csv, Binary };

struct OutputSettings {
  std::filesystem::path dir;  // relative to the working directory; default out/<name>
  int snapshotEveryYears = 10;
  SnapshotFormat snapshotFormat = SnapshotFormat::Csv;
  // The checkpoint (all plants) is rewritten every this many years, at the last year and
  // when a run is stopped; a run killed outright resumes from the last one written.
  int checkpointEveryYears = 1;
};

struct Scenario {
  std::filesystem::path file;
  std::string name;
  std::uint64_t seed = 1;
  TerrainSpec terrain;
  Climate climate;
  SimulationSettings simulation;
  std::vector<ScenarioSpecies> species;  // empty for terrain-only scenarios
  Plan plan;                             // planting, seed sources, areas kept open, thinning
  std::optional<ValidationSettings> validation;
  OutputSettings output;
};

Scenario loadScenario(const std::filesystem::path& file);

}  // namespace eco
