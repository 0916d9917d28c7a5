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
  EXPECT_EQ(defaults.simulation.lightRefreshYears, 2);
  EXPECT_DOUBLE_EQ(defaults.simulation.maxStemsPerHa, 1000.0);
  const Scenario s = loadScenario(write(R"([terrain]
cell_size_m = 5
[terrain.generate]
size = 9
[simulation]
years = 150
suitability = "product"
max_stems_per_ha = 600
light_directions = 24
light_refresh_years = 1
)"));
  EXPECT_EQ(s.simulation.years, 150);
  EXPECT_EQ(s.simulation.suitability, SuitabilityRule::Product);
  EXPECT_DOUBLE_EQ(s.simulation.maxStemsPerHa, 600.0);
  EXPECT_EQ(s.simulation.lightDirections, 24);
  EXPECT_EQ(s.simulation.lightRefreshYears, 1);
  EXPECT_NE(std::string(errorOf("[terrain]\ncell_size_m = 5\n[terrain.generate]\nsize = "
                                "9\n[simulation]\nlight_refresh_years = 0\n")
                            .what())
                .find("s.toml:6: simulation.light_refresh_years: value 0 is outside [1, 10]"),
            std::string::npos);
}

TEST(Scenario, GeneratedTerrainAndDefaults) {
  Scenario s = loadScenario(write("[terrain]\ncell_size_m = 5\n[terrain.generate]\nsize = 129\n"));
  ASSERT_TRUE(s.terrain.generate.has_value());
  EXPECT_EQ(s.terrain.generate->size, 129);
  EXPECT_DOUBLE_EQ(s.terrain.cellDx_m, 5.0);
  EXPECT_DOUBLE_EQ(s.terrain.cellDy_m, 5.0);
  EXPECT_DOUBLE_EQ(s.climate.latitude_deg, 46.0);
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
