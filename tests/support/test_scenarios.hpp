// Scenarios shared by the test suites of several modules (each links fmt).
#pragma once

#include <filesystem>
#include <string>

#include <fmt/format.h>

namespace eco::test {

// A 45 m plot of level ground planted with Scots pine and beech 2 m apart, grown 40 years,
// with binary snapshots (the simulation's diameters exactly) of years 20 and 40: the
// scenario's text, its species files from `dataDir`. Its pines pass 10 cm by year 40, so
// its stand has stems to tally.
inline std::string plantedPlotScenario(const std::filesystem::path& dataDir) {
  return fmt::format(R"(name = "planted_plot"
seed = 3
[terrain]
cell_size_m = 5
[terrain.generate]
size = 9
relief_m = 0
base_altitude_m = 400
[simulation]
years = 40
[[species]]
file = "{0}/species/pine.toml"
[[species]]
file = "{0}/species/beech.toml"
[[planting]]
species = {{ pine = 0.5, beech = 0.5 }}
spacing_m = 2.0
[output]
snapshot_every_years = 20
snapshot_format = "binary"
)",
                     dataDir.string());
}

}  // namespace eco::test
