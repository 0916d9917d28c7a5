#include "sim/ecology/species_ecology.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/toml_reader.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

std::string errorOf(const std::string& text) {
  try {
    const TomlDocument document = TomlDocument::parse(text, "eco.toml");
    TomlTable root = document.root();
    std::optional<TomlTable> ecology = root.table("ecology");
    parseEcology(*ecology);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const char* kLife = R"(
[ecology.life]
max_age_years = 100
max_height_m = 20.0
height_growth_rate = 0.05
height_growth_shape = 1.2
max_dbh_m = 0.5
dbh_growth_rate = 0.02
dbh_growth_shape = 1.1
crown_radius_m = [[0, 0.3], [0.5, 4.0]]
crown_ratio = 0.5
crown_transmittance = 0.2
maturity_age_years = 15
seeds_per_year = 10
germination = 0.4
dispersal = "wind"
dispersal_mean_m = 30.0
downwind_bias = 0.3
)";

TEST(Ecology, LightMinimaFollowEllenbergsDefinitions) {
  EXPECT_DOUBLE_EQ(lightCompensation(3), 0.02);  // shade plant, "mostly below 5 %"
  EXPECT_DOUBLE_EQ(lightCompensation(5), 0.10);  // "rarely below 10 %"
  EXPECT_DOUBLE_EQ(lightCompensation(7), 0.30);  // "rarely below 30 %"
  EXPECT_DOUBLE_EQ(lightCompensation(4), 0.06);
  EXPECT_DOUBLE_EQ(lightCompensation(0), 0.10);  // indifferent reads as L5
  const Polyline response = lightResponseFor(7);
  EXPECT_DOUBLE_EQ(response(0.2), 0.0);
  EXPECT_DOUBLE_EQ(response(0.45), 0.5);
  EXPECT_DOUBLE_EQ(response(0.9), 1.0);
}

TEST(Ecology, TolerancesDerivedFromEllenbergValues) {
  const ToleranceCurves t =
      deriveTolerances({.light = 3, .temperature = 5, .moisture = 5, .continentality = 2});
  // Moisture number F = 1 + 8 m: full within 1.5 units of F = 5, zero 3.5 units away.
  EXPECT_DOUBLE_EQ(t.moisture((5.0 - 1.0) / 8.0), 1.0);
  EXPECT_DOUBLE_EQ(t.moisture((5.0 - 1.5 - 1.0) / 8.0), 1.0);
  EXPECT_NEAR(t.moisture((5.0 - 2.5 - 1.0) / 8.0), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(t.moisture((5.0 + 3.5 - 1.0) / 8.0), 0.0);
  // T = 5 is the submontane belt: full from 75 m to 1425 m, zero above 2325 m.
  EXPECT_DOUBLE_EQ(t.altitude_m(750.0), 1.0);
  EXPECT_DOUBLE_EQ(t.altitude_m(1425.0), 1.0);
  EXPECT_NEAR(t.altitude_m(1875.0), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(t.altitude_m(2325.0), 0.0);
  // K = 2: exposure tolerated up to windiness 0.44, none past 0.84.
  EXPECT_DOUBLE_EQ(t.windiness(0.44), 1.0);
  EXPECT_NEAR(t.windiness(0.64), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(t.windiness(0.9), 0.0);
  EXPECT_DOUBLE_EQ(t.sunniness(0.02), 0.0);
  EXPECT_DOUBLE_EQ(t.sunniness(0.32), 1.0);
  // Indifferent ("x") values tolerate the whole range.
  const ToleranceCurves x = deriveTolerances({.light = 7});
  EXPECT_DOUBLE_EQ(x.moisture(0.0), 1.0);
  EXPECT_DOUBLE_EQ(x.altitude_m(3000.0), 1.0);
  EXPECT_DOUBLE_EQ(x.windiness(1.0), 1.0);
}

TEST(Ecology, GrowthCurveAndItsInverse) {
  const GrowthCurve c{40.0, 0.022, 1.6};
  EXPECT_EQ(c.at(0.0), 0.0);
  EXPECT_NEAR(c.at(100.0), 40.0 * std::pow(1.0 - std::exp(-2.2), 1.6), 1e-12);
  EXPECT_NEAR(c.ageOf(c.at(63.0)), 63.0, 1e-9);
  EXPECT_TRUE(std::isinf(c.ageOf(40.0)));
}

TEST(Ecology, ParsesAFileAndItsOverrides) {
  const TomlDocument document = TomlDocument::parse(std::string(R"(
[ecology]
ellenberg = { light = 6, temperature = "x", moisture = 4, continentality = 3 }
light_response = [[0.1, 0], [0.2, 1]]
[ecology.tolerance]
slope_deg = [[10, 1], [20, 0]]
)") + kLife,
                                                    "eco.toml");
  TomlTable root = document.root();
  std::optional<TomlTable> table = root.table("ecology");
  const Ecology e = parseEcology(*table);
  EXPECT_EQ(e.ellenberg.light, 6);
  EXPECT_EQ(e.ellenberg.temperature, 0);
  EXPECT_DOUBLE_EQ(e.lightResponse(0.15), 0.5);
  EXPECT_DOUBLE_EQ(e.tolerance.slope_deg(15.0), 0.5);
  EXPECT_DOUBLE_EQ(e.tolerance.moisture(0.375), 1.0);  // derived: F = 4
  EXPECT_EQ(e.life.dispersal, DispersalVector::Wind);
  EXPECT_DOUBLE_EQ(e.life.downwindBias, 0.3);
  EXPECT_DOUBLE_EQ(e.life.height_m.max, 20.0);
  EXPECT_EQ(e.life.longDistanceFraction, 0.0);  // a plain exponential kernel by default
}

TEST(Ecology, ALongDistanceShareNeedsALongerMean) {
  const std::string head =
      "[ecology]\nellenberg = { light = 3, temperature = 5, moisture = 5, continentality = 2 }\n";
  EXPECT_NE(errorOf(head + kLife + "long_distance_fraction = 0.1\n")
                .find("ecology.life.long_distance_mean_m: missing"),
            std::string::npos);
  EXPECT_NE(errorOf(head + kLife + "long_distance_fraction = 0.1\nlong_distance_mean_m = 20\n")
                .find("eco.toml:22: ecology.life.long_distance_mean_m: must be longer than "
                      "dispersal_mean_m"),
            std::string::npos);
  EXPECT_EQ(errorOf(head + kLife + "long_distance_fraction = 0.1\nlong_distance_mean_m = 300\n"),
            "no error");
}

TEST(Ecology, BadValuesAreReportedAtTheirLine) {
  EXPECT_NE(errorOf(std::string("[ecology]\nellenberg = { light = 3, temperature = \"y\", "
                                "moisture = 5, continentality = 2 }\n") +
                    kLife)
                .find("eco.toml:2: ecology.ellenberg.temperature: expected a number or \"x\""),
            std::string::npos);
  EXPECT_NE(errorOf(std::string("[ecology]\nellenberg = { light = 10, temperature = 5, "
                                "moisture = 5, continentality = 2 }\n") +
                    kLife)
                .find("ecology.ellenberg.light: value 10 is outside [1, 9]"),
            std::string::npos);
  std::string animal = kLife;
  animal.replace(animal.find("\"wind\""), 6, "\"animal\"");
  EXPECT_NE(errorOf("[ecology]\nellenberg = { light = 3, temperature = 5, moisture = 5, "
                    "continentality = 2 }\n" +
                    animal)
                .find("only wind-dispersed species drift downwind"),
            std::string::npos);
}

TEST(Ecology, ShippedSpeciesCarryTheirEllenbergValues) {
  auto shipped = [](const char* name) {
    return readEcology(std::filesystem::path(ECOFOREST_DATA_DIR) / "species" /
                       (std::string(name) + ".toml"));
  };
  const std::optional<Ecology> beech = shipped("beech"), pine = shipped("pine");
  const std::optional<Ecology> maple = shipped("maple"), hazel = shipped("shrub");
  ASSERT_TRUE(beech && pine && maple && hazel);
  EXPECT_EQ(beech->ellenberg.light, 3);
  EXPECT_EQ(pine->ellenberg.light, 7);
  EXPECT_EQ(maple->ellenberg.moisture, 6);
  EXPECT_EQ(hazel->ellenberg.moisture, 0);
  // Shade tolerance orders as the light values do.
  EXPECT_LT(beech->lightResponse(0.05), 1.0);
  EXPECT_GT(beech->lightResponse(0.05), maple->lightResponse(0.05));
  EXPECT_EQ(pine->lightResponse(0.05), 0.0);
}

}  // namespace
}  // namespace eco

namespace eco {
namespace {

TEST(Ecology, ASpeciesWithoutEcologyHasNone) {
  const auto file = test::freshDirectory("no_ecology") / "tree.toml";
  test::writeFile(file, "name = \"tree\"\n");
  EXPECT_FALSE(readEcology(file).has_value());
}

}  // namespace
}  // namespace eco
