#include "sim/scenario.hpp"

#include <fstream>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

std::filesystem::path write(const std::string& text) {
  auto file = test::freshDirectory("scenario") / "s.toml";
  std::ofstream(file) << text;
  return file;
}

InputError errorOf(const std::string& text) {
  try {
    loadScenario(write(text));
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError({}, "");
}

}  // namespace

TEST(Scenario, ReadsTheDocumentedExample) {
  auto file = write(R"(name = "valley"
seed = 42
[terrain]
heightmap = "terrain/valley.png"
cell_size_m = [10.0, 12.5]
height_range_m = [200.0, 900.0]
[climate]
latitude_deg = 46.0
prevailing_wind_from_deg = 270.0
annual_precipitation_mm = 1100.0
)");
  Scenario s = loadScenario(file);
  EXPECT_EQ(s.name, "valley");
  EXPECT_EQ(s.seed, 42u);
  EXPECT_EQ(*s.terrain.heightmap,
            file.parent_path() / "terrain/valley.png");  // relative to the file
  EXPECT_DOUBLE_EQ(s.terrain.cellDx_m, 10.0);
  EXPECT_DOUBLE_EQ(s.terrain.cellDy_m, 12.5);
  EXPECT_DOUBLE_EQ(*s.terrain.heightMax_m, 900.0);
  EXPECT_DOUBLE_EQ(s.climate.prevailingWindFrom_deg, 270.0);
}

TEST(Scenario, ReadsTheSimulationTable) {
  const Scenario defaults =
      loadScenario(write("[terrain]\ncell_size_m = 5\n[terrain.generate]\nsize = 9\n"));
  EXPECT_EQ(defaults.simulation.years, 100);
  EXPECT_EQ(defaults.simulation.suitability, SuitabilityRule::Minimum);
  const Scenario s = loadScenario(write(R"([terrain]
cell_size_m = 5
[terrain.generate]
size = 9
[simulation]
years = 150
suitability = "product"
)"));
  EXPECT_EQ(s.simulation.years, 150);
  EXPECT_EQ(s.simulation.suitability, SuitabilityRule::Product);
  EXPECT_NE(std::string(errorOf("[terrain]\ncell_size_m = 5\n[terrain.generate]\nsize = "
                                "9\n[simulation]\nyears = 0\n")
                            .what())
                .find("s.toml:6: simulation.years: value 0 is outside [1, 100000]"),
            std::string::npos);
}

TEST(Scenario, ReadsTheOutputTable) {
  const Scenario defaults =
      loadScenario(write("[terrain]\ncell_size_m = 5\n[terrain.generate]\nsize = 9\n"));
  EXPECT_EQ(defaults.output.snapshotEveryYears, 10);
  EXPECT_EQ(defaults.output.checkpointEveryYears, 1);
  EXPECT_EQ(defaults.output.snapshotFormat, SnapshotFormat::Csv);
  const std::string output = "[terrain]\ncell_size_m = 5\n[terrain.generate]\nsize = 9\n[output]\n";
  const Scenario s = loadScenario(write(output + "snapshot_every_years = 5\n"
                                                 "checkpoint_every_years = 25\n"
                                                 "snapshot_format = \"binary\"\n"));
  EXPECT_EQ(s.output.snapshotEveryYears, 5);
  EXPECT_EQ(s.output.checkpointEveryYears, 25);
  EXPECT_EQ(s.output.snapshotFormat, SnapshotFormat::Binary);
  EXPECT_NE(std::string(errorOf(output + "snapshot_format = \"parquet\"\n").what())
                .find("s.toml:6: output.snapshot_format: unknown snapshot format 'parquet' "
                      "(expected csv or binary)"),
            std::string::npos);
}

TEST(Scenario, ReadsTheValidationTable) {
  const Scenario s = loadScenario(write(R"([terrain]
cell_size_m = 5
[terrain.generate]
size = 9
[[planting]]
species = "beech"
[validation]
yield_table = "table.csv"
species = "beech"
checked_ages = [100, 140]
)"));
  ASSERT_TRUE(s.validation.has_value());
  EXPECT_EQ(s.validation->yieldTable, s.file.parent_path() / "table.csv");
  EXPECT_EQ(s.validation->species, "beech");
  EXPECT_EQ(s.validation->checkedAges, (std::vector<int>{100, 140}));
  EXPECT_DOUBLE_EQ(s.validation->tolerance, 0.15);
  EXPECT_EQ(s.validation->thinningFrom_years, 60);
  EXPECT_EQ(s.validation->thinningTo_years, 120);
  EXPECT_DOUBLE_EQ(s.validation->steepestThinningSlope, -2.0);
  const std::string planted =
      "[terrain]\ncell_size_m = 5\n[terrain.generate]\nsize = 9\n"
      "[[planting]]\nspecies = \"b\"\n";
  EXPECT_NE(std::string(errorOf(planted + "[validation]\nyield_table = \"t.csv\"\nspecies = \"b\"\n"
                                          "self_thinning_slope = [-1.3, -2.0]\n")
                            .what())
                .find("s.toml:10: validation.self_thinning_slope: expected [steepest, shallowest]"),
            std::string::npos);
  EXPECT_NE(
      std::string(
          errorOf(planted + "[validation]\nyield_table = \"t.csv\"\nspecies = \"oak\"\n").what())
          .find("s.toml:9: validation.species: 'oak' is not planted"),
      std::string::npos);
}

TEST(Scenario, ClimateTemperatureFallsWithTheLapseRate) {
  const Scenario s = loadScenario(write(R"([terrain]
cell_size_m = 5
[terrain.generate]
size = 9
[climate]
mean_annual_temperature_c = 8.5
temperature_altitude_m = 400
lapse_rate_k_per_m = 0.006
)"));
  EXPECT_DOUBLE_EQ(s.climate.temperatureAt(400.0), 8.5);
  EXPECT_NEAR(s.climate.temperatureAt(1400.0), 2.5, 1e-12);  // 1 km higher, 6 K colder
  EXPECT_NEAR(s.climate.temperatureAt(0.0), 10.9, 1e-12);
  // The defaults: 9.5 degC at 300 m, the standard atmosphere's 6.5 K per km.
  EXPECT_NEAR(Climate{}.temperatureAt(1300.0), 3.0, 1e-12);
}

TEST(Scenario, ReadsTheSpeciesAndTheirSeedSources) {
  const Scenario s = loadScenario(write(R"([terrain]
cell_size_m = 5
[terrain.generate]
size = 9
[[species]]
file = "species/beech.toml"
seed_rain_per_ha_per_year = 2.5
surrounding_forest_share = 0.33
[[species]]
file = "species/pine.toml"
)"));
  ASSERT_EQ(s.species.size(), 2u);
  EXPECT_EQ(s.species[0].file, s.file.parent_path() / "species/beech.toml");
  EXPECT_DOUBLE_EQ(s.species[0].seedRainPerHaPerYear, 2.5);
  EXPECT_DOUBLE_EQ(s.species[0].surroundingForestShare, 0.33);
  EXPECT_DOUBLE_EQ(s.species[1].surroundingForestShare, 0.0);
  EXPECT_NE(std::string(errorOf("[terrain]\ncell_size_m = 5\n[terrain.generate]\nsize = 9\n"
                                "[[species]]\nfile = \"b.toml\"\nsurrounding_forest_share = 2\n")
                            .what())
                .find("s.toml:7: species[0].surrounding_forest_share: value 2 is outside [0, 1]"),
            std::string::npos);
}

TEST(Scenario, ReadsPlantings) {
  const Scenario s = loadScenario(write(R"([terrain]
cell_size_m = 5
[terrain.generate]
size = 9
[[planting]]
species = "beech"
spacing_m = 1.5
height_m = 0.4
[[planting]]
species = "pine"
)"));
  const std::vector<Planting>& planting = s.plan.planting;
  ASSERT_EQ(planting.size(), 2u);
  EXPECT_EQ(planting[0].speciesNames(), std::vector<std::string>{"beech"});
  EXPECT_DOUBLE_EQ(planting[0].spacing_m, 1.5);
  EXPECT_DOUBLE_EQ(planting[0].height_m, 0.4);
  EXPECT_EQ(planting[0].region.kind, RegionSpec::Kind::WholeMap);
  EXPECT_EQ(planting[0].year, 1);
  EXPECT_EQ(planting[1].speciesNames(), std::vector<std::string>{"pine"});
  EXPECT_DOUBLE_EQ(planting[1].spacing_m, 2.0);
  EXPECT_EQ(planting[1].where.line, 10);
  EXPECT_NE(std::string(errorOf("[terrain]\ncell_size_m = 5\n[terrain.generate]\nsize = "
                                "9\n[[planting]]\nspecies = \"beech\"\nheight_m = 5\n")
                            .what())
                .find("s.toml:7: planting[0].height_m: value 5 is outside [0.05, 3.99]"),
            std::string::npos);
}

TEST(Scenario, GeneratedTerrainAndDefaults) {
  Scenario s = loadScenario(write("[terrain]\ncell_size_m = 5\n[terrain.generate]\nsize = 129\n"));
  ASSERT_TRUE(s.terrain.generate.has_value());
  EXPECT_EQ(s.terrain.generate->size, 129);
  EXPECT_DOUBLE_EQ(s.terrain.cellDx_m, 5.0);
  EXPECT_DOUBLE_EQ(s.terrain.cellDy_m, 5.0);
  EXPECT_DOUBLE_EQ(s.climate.latitude_deg, 46.0);
  EXPECT_EQ(s.terrain.closedDepressions, ClosedDepressions::Drain);
}

TEST(Scenario, ClosedDepressionsDrainOrHoldPonds) {
  const Scenario ponds = loadScenario(write(
      "[terrain]\ncell_size_m = 5\nclosed_depressions = \"pond\"\n[terrain.generate]\nsize = 9\n"));
  EXPECT_EQ(ponds.terrain.closedDepressions, ClosedDepressions::Pond);
  InputError lake = errorOf("[terrain]\nheightmap = \"a.png\"\nclosed_depressions = \"lake\"\n");
  EXPECT_EQ(lake.where().line, 3);
  EXPECT_EQ(lake.where().key, "terrain.closed_depressions");
  EXPECT_NE(std::string(lake.what()).find("expected drain or pond"), std::string::npos);
}

TEST(Scenario, BadInputNamesTheLineAndKey) {
  InputError zero = errorOf("[terrain]\nheightmap = \"a.png\"\ncell_size_m = 0\n");
  EXPECT_EQ(zero.where().line, 3);
  EXPECT_EQ(zero.where().key, "terrain.cell_size_m");
  InputError negative = errorOf("[terrain]\nheightmap = \"a.png\"\ncell_size_m = [10, -1]\n");
  EXPECT_EQ(negative.where().line, 3);
  InputError unknown = errorOf("[terrain]\nheightmap = \"a.png\"\n[climate]\nlatitude = 46\n");
  EXPECT_EQ(unknown.where().line, 4);
  EXPECT_EQ(unknown.where().key, "climate.latitude");
  InputError neither = errorOf("[terrain]\ncell_size_m = 10\n");
  EXPECT_NE(std::string(neither.what()).find("heightmap"), std::string::npos);
  InputError both = errorOf("[terrain]\nheightmap = \"a.png\"\n[terrain.generate]\nsize = 33\n");
  EXPECT_NE(std::string(both.what()).find("not both"), std::string::npos);
  InputError size = errorOf("[terrain]\n[terrain.generate]\nsize = 100\n");
  EXPECT_EQ(size.where().line, 3);
  InputError type = errorOf("seed = \"x\"\n[terrain]\nheightmap = \"a.png\"\n");
  EXPECT_EQ(type.where().line, 1);
  EXPECT_THROW(loadScenario("/nonexistent/s.toml"), InputError);
}

}  // namespace eco
