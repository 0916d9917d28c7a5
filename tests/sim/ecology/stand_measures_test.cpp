#include "sim/ecology/stand_measures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/random.hpp"
#include "ecosystem_support.hpp"

namespace eco {
namespace {

void addTree(Plants& p, int species, float east, float north, float dbh, float height) {
  const std::size_t i = p.size();
  p.resize(i + 1);
  p.id[i] = i + 1;
  p.species[i] = static_cast<std::uint8_t>(species);
  p.east_m[i] = east, p.north_m[i] = north;
  p.dbh_m[i] = dbh, p.height_m[i] = height;
  p.alive[i] = 1;
}

TEST(StandMeasures, CountsWhatAForesterCalipers) {
  const std::vector<EcosystemSpecies> species = {test::shippedSpecies("beech"),
                                                 test::shippedSpecies("pine")};
  Plants p;
  addTree(p, 0, 10, 10, 0.30f, 30.0f);
  addTree(p, 0, 20, 10, 0.40f, 32.0f);
  addTree(p, 1, 30, 10, 0.20f, 25.0f);
  addTree(p, 0, 40, 10, 0.05f, 6.0f);  // below the calipering limit
  const std::vector<StandMeasures> measures = measureStands(p, species, 0.5);
  ASSERT_EQ(measures.size(), 3u);  // beech, pine, and all
  const StandMeasures& all = measures[2];
  EXPECT_DOUBLE_EQ(all.stemsPerHa, 6.0);
  const double ba = std::numbers::pi / 4 * (0.09 + 0.16 + 0.04);
  EXPECT_NEAR(all.basalArea_m2PerHa, ba / 0.5, 1e-6);
  EXPECT_NEAR(all.qmd_cm, 100.0 * std::sqrt((0.09 + 0.16 + 0.04) / 3.0), 1e-4);
  // Reineke: the stems a stand of 25.4 cm mean diameter would have.
  EXPECT_NEAR(all.sdi, 6.0 * std::pow(all.qmd_cm / 25.4, 1.605), 1e-9);
  const double f0 = species[0].ecology.life.formFactor, f1 = species[1].ecology.life.formFactor;
  EXPECT_NEAR(all.volume_m3PerHa,
              std::numbers::pi / 4 * (f0 * 0.09 * 30 + f0 * 0.16 * 32 + f1 * 0.04 * 25) / 0.5,
              1e-4);
  // On half a hectare the 50 tallest: here all four plants.
  EXPECT_NEAR(all.dominantHeight_m, (30.0 + 32.0 + 25.0 + 6.0) / 4.0, 1e-6);
  EXPECT_DOUBLE_EQ(measures[1].stemsPerHa, 2.0);  // pine
  EXPECT_DOUBLE_EQ(measures[0].stemsPerHa, 4.0);  // beech
  EXPECT_NEAR(measures[0].basalArea_m2PerHa + measures[1].basalArea_m2PerHa, all.basalArea_m2PerHa,
              1e-12);
  EXPECT_NEAR(measures[1].dominantHeight_m, 25.0, 1e-6);  // its only tree
  // Every plant counts in the plants and their mean height, the thin one too.
  EXPECT_EQ(all.plants, 4u);
  EXPECT_NEAR(all.meanHeight_m, (30.0 + 32.0 + 25.0 + 6.0) / 4.0, 1e-6);
  EXPECT_EQ(measures[0].plants, 3u);
}

TEST(StandMeasures, DominantHeightIsTheMeanOfTheHundredTallestPerHectare) {
  const std::vector<EcosystemSpecies> species = {test::shippedSpecies("beech")};
  Plants p;
  for (int i = 0; i < 400; ++i) addTree(p, 0, 1.0f * i, 0, 0.2f, static_cast<float>(i % 40));
  // One hectare: the 100 tallest are ten each of 30..39 m.
  EXPECT_NEAR(measureStands(p, species, 1.0).back().dominantHeight_m, 34.5, 1e-9);
}

// Mostly seedlings, a canopy around 30 m with many in one height class, and a few giants
// taller than the last class's lower edge; every third plant a pine. More plants than three
// blocks (kPlantBlock), whose sums are combined in order.
Plants mixedStand() {
  Plants p;
  Rng rng(7);
  for (std::size_t i = 0; i < 3 * kPlantBlock + 1234; ++i) {
    const double pick = rng.uniform();
    const double height = pick < 0.7    ? 0.1 + 1.2 * rng.uniform()
                          : pick < 0.8  ? 30.0 + 0.2 * rng.uniform()
                          : pick < 0.99 ? 1.3 + 40.0 * rng.uniform()
                                        : 120.0 + 30.0 * rng.uniform();
    const float dbh = height >= 1.3 ? static_cast<float>(0.02 + 0.5 * rng.uniform()) : 0.0f;
    addTree(p, i % 3 == 0 ? 1 : 0, 0.0f, 0.0f, dbh, static_cast<float>(height));
  }
  return p;
}

const std::vector<EcosystemSpecies>& beechAndPine() {
  static const std::vector<EcosystemSpecies> species = {test::shippedSpecies("beech"),
                                                        test::shippedSpecies("pine")};
  return species;
}

TEST(StandMeasures, DominantHeightAgreesWithASortOfEveryHeight) {
  // The tallest are looked for in the top height classes only; whatever stand size puts the
  // hundredth per hectare, a sort of every height gives the same mean.
  const std::vector<EcosystemSpecies>& species = beechAndPine();
  const Plants p = mixedStand();
  for (const double area_ha : {0.01, 0.5, 2.0, 7.3, 30.0, 60.0}) {
    const std::vector<StandMeasures> measures = measureStands(p, species, area_ha);
    for (std::size_t group = 0; group < measures.size(); ++group) {
      std::vector<float> heights;
      for (std::size_t i = 0; i < p.size(); ++i)
        if (group == species.size() || p.species[i] == group) heights.push_back(p.height_m[i]);
      std::sort(heights.begin(), heights.end(), std::greater<>());
      const std::size_t tallest =
          std::min(heights.size(), static_cast<std::size_t>(std::round(100.0 * area_ha)));
      double sum = 0.0;
      for (std::size_t k = 0; k < tallest; ++k) sum += heights[k];
      EXPECT_NEAR(measures[group].dominantHeight_m, sum / static_cast<double>(tallest), 1e-9)
          << area_ha << " ha, group " << group;
    }
  }
}

TEST(StandMeasures, TheBlocksSumsAreThoseOfOnePassInPlantOrder) {
  const std::vector<EcosystemSpecies>& species = beechAndPine();
  const Plants p = mixedStand();
  const double area_ha = 12.0;
  const std::vector<StandMeasures> measures = measureStands(p, species, area_ha);
  for (std::size_t group = 0; group < measures.size(); ++group) {
    StandTally tally;
    std::size_t plants = 0;
    double heights_m = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (group == species.size() || p.species[i] == group) {
        tally.add(p.dbh_m[i], p.height_m[i], species[p.species[i]].ecology.life.formFactor);
        ++plants;
        heights_m += p.height_m[i];
      }
    const StandMeasures one = tally.perHectare(area_ha);
    const StandMeasures& blocks = measures[group];
    EXPECT_EQ(blocks.plants, plants) << group;
    EXPECT_DOUBLE_EQ(blocks.stemsPerHa, one.stemsPerHa) << group;
    EXPECT_NEAR(blocks.basalArea_m2PerHa, one.basalArea_m2PerHa, 1e-12 * one.basalArea_m2PerHa);
    EXPECT_NEAR(blocks.qmd_cm, one.qmd_cm, 1e-12 * one.qmd_cm);
    EXPECT_NEAR(blocks.volume_m3PerHa, one.volume_m3PerHa, 1e-12 * one.volume_m3PerHa);
    EXPECT_NEAR(blocks.meanHeight_m, heights_m / static_cast<double>(plants), 1e-12 * 30.0);
  }
  EXPECT_EQ(measures[0].plants + measures[1].plants, p.size());
}

TEST(StandMeasures, TheDensestBlockIsFoundWhereverItLies) {
  const Grid grid{30, 20, 10.0, 10.0};  // 300 m x 200 m: 3 x 2 blocks of a hectare
  Plants p;
  for (int i = 0; i < 10; ++i) addTree(p, 0, 250.0f, 150.0f + i, 0.4f, 30.0f);
  for (int i = 0; i < 3; ++i) addTree(p, 0, 20.0f, 20.0f + i, 0.4f, 30.0f);
  addTree(p, 0, 290.0f, 10.0f, 0.05f, 5.0f);  // too thin to count
  EXPECT_NEAR(densestBlockBasalArea(p, grid), 10 * std::numbers::pi / 4 * 0.16, 1e-5);
  EXPECT_EQ(densestBlockBasalArea(p, Grid{5, 5, 10.0, 10.0}), 0.0);  // smaller than a block
}

}  // namespace
}  // namespace eco
