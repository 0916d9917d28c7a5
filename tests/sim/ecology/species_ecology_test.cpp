#include "sim/ecology/species_ecology.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/toml_reader.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

// The [ecology] table of a species file's text, parsed.
Ecology ecologyOf(const std::string& text) {
  const TomlDocument document = TomlDocument::parse(text, "eco.toml");
  TomlTable root = document.root();
  std::optional<TomlTable> ecology = root.table("ecology");
  return parseEcology(*ecology);
}

std::string errorOf(const std::string& text) {
  try {
    ecologyOf(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// The line of the first `key = ` in a text, counting from 1.
int lineOf(const std::string& text, const std::string& key) {
  const std::size_t at = text.find("\n" + key + " = ");
  return 2 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

const char* kHead =
    "[ecology]\nellenberg = { light = 3, temperature = 5, moisture = 5 }\nwind_firmness = 160\n";

const char* kLife = R"(
[ecology.life]
max_age_years = 100
max_height_m = 20.0
height_growth_rate = 0.05
height_growth_shape = 1.2
form_factor = 0.45
foliage_biomass = [0.02, 1.7]
stem_biomass = [0.2, 2.3]
branch_biomass = [0.02, 2.3]
coarse_root_biomass = [0.02, 2.3]
specific_leaf_area_m2_per_kg = 10.0
leaf_turnover_per_year = 1.0
fine_root_foliage_ratio = 0.75
fine_root_turnover_per_year = 1.0
crown_diameter_silva = [0.34, 0.33, 0.0145, -0.041]
crown_ratio = 0.5
light_use_efficiency = 1.5
maturity_age_years = 15
fecundity_per_m2 = 10
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
  // 10 degC at sea level, 5 K colder per km: 200 m per degree.
  Climate climate;
  climate.meanAnnualTemperature_c = 10.0;
  climate.temperatureAltitude_m = 0.0;
  climate.lapseRate_K_per_m = 0.005;
  const ToleranceCurves t =
      deriveTolerances({.light = 3, .temperature = 5, .moisture = 5}, 160.0, climate);
  // The site's F against the species' F = 5: full within 1.5 units, zero 3.5 units away.
  EXPECT_DOUBLE_EQ(t.moisture(5.0), 1.0);
  EXPECT_DOUBLE_EQ(t.moisture(3.5), 1.0);
  EXPECT_NEAR(t.moisture(2.5), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(t.moisture(8.5), 0.0);
  EXPECT_DOUBLE_EQ(t.moisture(1.5), 0.0);
  // T = 5 is 7 degC, 1.5 K per unit: full from 9.25 degC (150 m) to 4.75 degC (1050 m),
  // none at 1.75 degC (1650 m).
  EXPECT_DOUBLE_EQ(t.altitude_m(150.0), 1.0);
  EXPECT_DOUBLE_EQ(t.altitude_m(1050.0), 1.0);
  EXPECT_NEAR(t.altitude_m(1350.0), 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(t.altitude_m(1650.0), 0.0);
  EXPECT_NEAR(altitudeOfTemperature(7.0, climate), 600.0, 1e-9);
  // The same species in a climate 3 K warmer lives 600 m higher.
  climate.meanAnnualTemperature_c = 13.0;
  const ToleranceCurves warm =
      deriveTolerances({.light = 3, .temperature = 5, .moisture = 5}, 160.0, climate);
  EXPECT_NEAR(warm.altitude_m(1950.0), 0.5, 1e-9);
  // Wind firmness 160 bears windiness 0.5 fully and none from 0.85; a weaker stem less.
  EXPECT_DOUBLE_EQ(t.windiness(0.5), 1.0);
  EXPECT_NEAR(t.windiness(0.675), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(t.windiness(0.85), 0.0);
  const ToleranceCurves weak = deriveTolerances({.light = 3}, 110.0, climate);
  EXPECT_DOUBLE_EQ(weak.windiness(0.75), 0.0);
  EXPECT_DOUBLE_EQ(weak.windiness(0.4), 1.0);
  // Indifferent ("x") values tolerate the whole range.
  const ToleranceCurves x = deriveTolerances({.light = 7}, 160.0, climate);
  EXPECT_DOUBLE_EQ(x.moisture(1.0), 1.0);
  EXPECT_DOUBLE_EQ(x.moisture(12.0), 1.0);
  EXPECT_DOUBLE_EQ(x.altitude_m(3000.0), 1.0);
}

TEST(Ecology, GrowthCurveAndItsYearOn) {
  const GrowthCurve c{40.0, 0.022, 1.6};
  EXPECT_EQ(c.at(0.0), 0.0);
  EXPECT_NEAR(c.at(100.0), 40.0 * std::pow(1.0 - std::exp(-2.2), 1.6), 1e-12);
  // A year on from any point of the curve, in closed form, is the round trip through the age.
  for (double age : {0.0, 0.5, 7.0, 63.0, 250.0})
    EXPECT_NEAR(c.yearAfter(c.at(age)), c.at(age + 1.0), kGrowthPrecision * c.at(age + 1.0)) << age;
  EXPECT_EQ(c.yearAfter(40.0), 40.0);
  EXPECT_EQ(c.yearAfter(41.0), 40.0);
}

TEST(Ecology, ParsesAFileAndItsOverrides) {
  const Ecology e = ecologyOf(std::string(R"(
[ecology]
ellenberg = { light = 6, temperature = "x", moisture = 4 }
wind_firmness = 150
light_response = [[0.1, 0], [0.2, 1]]
[ecology.tolerance]
slope_deg = [[10, 1], [20, 0]]
)") + kLife);
  EXPECT_EQ(e.ellenberg.light, 6);
  EXPECT_EQ(e.ellenberg.temperature, 0);
  EXPECT_DOUBLE_EQ(e.lightResponse(0.15), 0.5);
  const ToleranceCurves t = e.tolerances(Climate{});
  EXPECT_DOUBLE_EQ(t.slope_deg(15.0), 0.5);
  EXPECT_DOUBLE_EQ(t.moisture(4.0), 1.0);  // derived: F = 4
  EXPECT_DOUBLE_EQ(t.moisture(8.0), 0.0);
  EXPECT_DOUBLE_EQ(e.windFirmness, 150.0);
  EXPECT_NEAR(e.life.foliage.at(10.0), 0.02 * std::pow(10.0, 1.7), kGrowthPrecision);
  EXPECT_DOUBLE_EQ(e.life.lightUseEfficiency, 1.5);
  EXPECT_EQ(e.life.dispersal, DispersalVector::Wind);
  EXPECT_DOUBLE_EQ(e.life.downwindBias, 0.3);
  EXPECT_DOUBLE_EQ(e.life.height_m.max(), 20.0);
  EXPECT_EQ(e.life.longDistanceFraction, 0.0);  // a plain exponential kernel by default
  EXPECT_EQ(e.life.aging.halfAt, 0.0);          // and no aging
  EXPECT_EQ(e.life.litterEstablishment, 1.0);   // seeds take on any ground by default
  EXPECT_EQ(e.life.swardEstablishment, 1.0);
}

TEST(Ecology, SeedbedEstablishmentIsAShareOfBareSoils) {
  const std::string file = std::string(kHead) + kLife;
  const Ecology e = ecologyOf(file + "litter_establishment = 0.3\nsward_establishment = 0.4\n");
  EXPECT_DOUBLE_EQ(e.life.litterEstablishment, 0.3);
  EXPECT_DOUBLE_EQ(e.life.swardEstablishment, 0.4);
  const std::string tooMuch = file + "sward_establishment = 1.5\n";
  EXPECT_NE(errorOf(tooMuch).find(fmt::format(
                "eco.toml:{}: ecology.life.sward_establishment: value 1.5 is outside [0, 1]",
                lineOf(tooMuch, "sward_establishment"))),
            std::string::npos)
      << errorOf(tooMuch);
}

// iLand's fecundity counts potential seedlings, seeds that survive to germinate, so a
// species file that takes it loses none of them again unless it says so.
TEST(Ecology, FecundityCountsSeedlingsSoNoSeedIsLostByDefault) {
  const std::string line = "germination = 0.4\n";
  std::string withoutGermination = kLife;
  withoutGermination.erase(withoutGermination.find(line), line.size());
  EXPECT_DOUBLE_EQ(ecologyOf(kHead + withoutGermination).life.germination, 1.0);
  EXPECT_DOUBLE_EQ(ecologyOf(std::string(kHead) + kLife).life.germination, 0.4);
}

TEST(Ecology, AgingIsReadAsILandsCurve) {
  const std::string file = std::string(kHead) + kLife;
  const Ecology e = ecologyOf(file + "aging = [0.8, 2.0]\n");
  EXPECT_DOUBLE_EQ(e.life.aging.halfAt, 0.8);
  EXPECT_DOUBLE_EQ(e.life.aging.exponent, 2.0);
  EXPECT_NE(errorOf(file + "aging = [0.8]\n").find("ecology.life.aging"), std::string::npos);
  EXPECT_NE(errorOf(file + "aging = [0.0, 2.0]\n").find("ecology.life.aging"), std::string::npos);
}

TEST(Ecology, ALongDistanceShareNeedsALongerMean) {
  const std::string head = kHead;
  EXPECT_NE(errorOf(head + kLife + "long_distance_fraction = 0.1\n")
                .find("ecology.life.long_distance_mean_m: missing"),
            std::string::npos);
  const std::string tooShort =
      head + kLife + "long_distance_fraction = 0.1\nlong_distance_mean_m = 20\n";
  EXPECT_NE(errorOf(tooShort).find(
                fmt::format("eco.toml:{}: ecology.life.long_distance_mean_m: must be longer than "
                            "dispersal_mean_m",
                            lineOf(tooShort, "long_distance_mean_m"))),
            std::string::npos);
  EXPECT_EQ(errorOf(head + kLife + "long_distance_fraction = 0.1\nlong_distance_mean_m = 300\n"),
            "no error");
}

TEST(Ecology, BadValuesAreReportedAtTheirLine) {
  EXPECT_NE(errorOf(std::string("[ecology]\nellenberg = { light = 3, temperature = \"y\", "
                                "moisture = 5 }\nwind_firmness = 160\n") +
                    kLife)
                .find("eco.toml:2: ecology.ellenberg.temperature: expected a number or \"x\""),
            std::string::npos);
  EXPECT_NE(errorOf(std::string("[ecology]\nellenberg = { light = 10, temperature = 5, "
                                "moisture = 5 }\nwind_firmness = 160\n") +
                    kLife)
                .find("ecology.ellenberg.light: value 10 is outside [1, 9]"),
            std::string::npos);
  std::string animal = kLife;
  animal.replace(animal.find("\"wind\""), 6, "\"animal\"");
  EXPECT_NE(errorOf(kHead + animal).find("only wind-dispersed species drift downwind"),
            std::string::npos);
  std::string noLue = kLife;
  noLue.erase(noLue.find("light_use_efficiency"), noLue.find("maturity") - noLue.find("light_use"));
  EXPECT_NE(errorOf(kHead + noLue).find("ecology.life.light_use_efficiency: missing"),
            std::string::npos);
  std::string badAllometry = kLife;
  badAllometry.replace(badAllometry.find("[0.02, 1.7]"), 11, "[0.0, 1.7]");
  EXPECT_NE(errorOf(kHead + badAllometry)
                .find(fmt::format("eco.toml:{}: ecology.life.foliage_biomass: expected [a, b]",
                                  lineOf(kHead + badAllometry, "foliage_biomass"))),
            std::string::npos);
}

TEST(Ecology, AgesAndPoorYearsAreRefusedBeyondWhatAPlantKeeps) {
  // A plant keeps its age in 16 bits and its poor years in 8 (plants.hpp).
  std::string old = kLife;
  old.replace(old.find("max_age_years = 100"), 19, "max_age_years = 10001");
  EXPECT_NE(errorOf(kHead + old).find("ecology.life.max_age_years: value 10001 is outside"),
            std::string::npos);
  old.replace(old.find("max_age_years = 10001"), 21, "max_age_years = 10000");
  EXPECT_EQ(ecologyOf(kHead + old).life.maxAge_years, kLongestLife_years);
  EXPECT_NE(errorOf(std::string(kHead) + kLife + "sapling_stress_years = 256\n")
                .find("ecology.life.sapling_stress_years: value 256 is outside [1, 255]"),
            std::string::npos);
  EXPECT_EQ(ecologyOf(std::string(kHead) + kLife + "sapling_stress_years = 255\n")
                .life.saplingStressYears,
            kMostSaplingStressYears);
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
