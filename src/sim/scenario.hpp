// Scenario files (docs/scenario.md): where the landscape comes from and its climate.
// Paths are relative to the scenario file. Later parts of the product add their tables
// (simulation, species, output) here.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace eco {

struct GeneratedTerrain {
  int size = 513;           // cells per side; midpoint displacement needs 2^n + 1
  double roughness = 0.55;  // amplitude kept from one subdivision level to the next
  double relief_m = 600.0;  // height difference between the lowest and highest cell
};

struct TerrainSpec {
  std::optional<std::filesystem::path> heightmap;  // absolute after loading
  std::optional<GeneratedTerrain> generate;        // exactly one of the two
  double cellDx_m = 10.0;
  double cellDy_m = 10.0;
  std::optional<double> heightMin_m, heightMax_m;  // height_range_m
  double baseAltitude_m = 0.0;                     // generated terrain: height of its lowest cell
};

struct Climate {
  double latitude_deg = 46.0;
  double prevailingWindFrom_deg = 270.0;
  double annualPrecipitation_mm = 1100.0;
};

struct Scenario {
  std::filesystem::path file;
  std::string name;
  std::uint64_t seed = 1;
  TerrainSpec terrain;
  Climate climate;
};

Scenario loadScenario(const std::filesystem::path& file);

}  // namespace eco
