#include "sim/ecology/ecosystem.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "ecosystem_support.hpp"
#include "sim/ecology/growth.hpp"
#include "terrain_support.hpp"

namespace eco {
namespace {

using test::TestEcology;

Terrain flat(int cells, double cell_m) {
  return test::analyticTerrain(cells, cells, cell_m, cell_m, [](double, double) { return 300.0; });
}

EcosystemSettings settingsWith(double maxSeedlingsPerHa = 1000.0) {
  EcosystemSettings s;
  s.seed = 11;
  s.simulation.maxSeedlingsPerHa = maxSeedlingsPerHa;
  s.simulation.lightDirections = 8;
  return s;
}

// A single species on flat, uniform ground spreads from one source as its dispersal kernel
// implies: the seedlings of one year lie at the kernel's mean distance from the source.
TEST(Ecosystem, SeedlingsFromOneSourceLieAtTheKernelsMeanDistance) {
  const Terrain terrain = flat(81, 5.0);  // 400 m across: 10 mean distances to the edge
  const ConditionFields fields = test::uniformConditions(terrain);
  TestEcology e;
  e.ecologyLines = "light_response = [[0, 1]]";  // shade does not matter here
  e.seedsPerYear = 4000.0;
  e.germination = 1.0;
  e.dispersalMean_m = 20.0;
  Ecosystem ecosystem(terrain, {test::inEcosystem(test::testSpecies("spreader", e), fields)},
                      settingsWith(1e6));
  const double centre = 200.0;
  ecosystem.plant(0, centre, centre, 60);
  ecosystem.step();
  const Plants& p = ecosystem.plants();
  ASSERT_GT(p.size(), 3000u);
  double sum = 0.0;
  for (std::size_t i = 1; i < p.size(); ++i)
    sum += std::hypot(p.east_m[i] - centre, p.north_m[i] - centre);
  const double mean = sum / static_cast<double>(p.size() - 1);
  // The standard error of the mean of an exponential distance is mean / sqrt(n) < 2 %.
  EXPECT_NEAR(mean, 20.0, 1.5);
  EXPECT_EQ(ecosystem.bornLastYear()[0], static_cast<int>(p.size() - 1));
}

TEST(Ecosystem, SpeciesExcludedFromTheUpperHalfNeverEstablishesThere) {
  // A slope from 0 m in the south to 1000 m in the north; tolerance ends at 500 m.
  const Terrain terrain = test::analyticTerrain(
      40, 40, 10.0, 10.0, [](double, double north) { return north * 1000.0 / 390.0; });
  ConditionFields fields = test::uniformConditions(terrain);
  TestEcology e;
  e.toleranceLines = "altitude_m = [[0, 1], [490, 1], [500, 0]]";
  e.maturityAge_years = 5;
  Ecosystem ecosystem(terrain, {test::inEcosystem(test::testSpecies("lowland", e), fields, 50.0)},
                      settingsWith());
  for (int year = 0; year < 25; ++year) ecosystem.step();
  const Plants& p = ecosystem.plants();
  ASSERT_GT(p.size(), 500u);
  for (std::size_t i = 0; i < p.size(); ++i)
    EXPECT_LT(p.ground_m[i], 500.0f) << "plant " << p.id[i];
}

TEST(Ecosystem, NoPlantGrowsTallerThanItsSpeciesMaximum) {
  const Terrain terrain = flat(24, 10.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  TestEcology fast;
  fast.maxHeight_m = 12.0;
  Ecosystem ecosystem(terrain, {test::inEcosystem(test::testSpecies("short", fast), fields, 20.0)},
                      settingsWith());
  for (int year = 0; year < 80; ++year) ecosystem.step();
  const Plants& p = ecosystem.plants();
  float tallest = 0.0f;
  for (float h : p.height_m) tallest = std::max(tallest, h);
  EXPECT_LE(tallest, 12.0f);
  EXPECT_GT(tallest, 9.0f);  // and they do grow toward it
}

TEST(Ecosystem, LightUnderADenseCanopyIsLowerThanInAGap) {
  const Terrain terrain = flat(30, 10.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  Ecosystem ecosystem(terrain, {test::inEcosystem(test::testSpecies("shade", {}), fields)},
                      settingsWith());
  // Old trees 5 m apart over the western half; the eastern half is open.
  for (double east = 2.5; east < 140.0; east += 5.0)
    for (double north = 2.5; north < 295.0; north += 5.0) ecosystem.plant(0, east, north, 80);
  ecosystem.step();  // builds this year's crowns
  const Grid& g = terrain.grid;
  const double underCanopy = ecosystem.groundLight(g.index(7, 15));
  const double inGap = ecosystem.groundLight(g.index(26, 15));
  EXPECT_LT(underCanopy, 0.1);
  EXPECT_GT(inGap, 0.5);
}

// Pines colonise an open field first; beech, which regenerates in their shade, takes over
// the canopy from them.
TEST(Ecosystem, ShadeTolerantBeechReplacesPioneerPine) {
  const Terrain terrain = flat(24, 10.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  EcosystemSpecies beech = test::shippedSpecies("beech");
  EcosystemSpecies pine = test::shippedSpecies("pine");
  Ecosystem ecosystem(
      terrain, {test::inEcosystem(beech, fields, 2.0), test::inEcosystem(pine, fields, 20.0)},
      settingsWith());
  auto canopyShare = [&](int species) {
    const Plants& p = ecosystem.plants();
    int of = 0, all = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.height_m[i] > 5.0f) ++all, of += p.species[i] == species;
    return all ? static_cast<double>(of) / all : 0.0;
  };
  for (int year = 0; year < 40; ++year) ecosystem.step();
  const double pineEarly = canopyShare(1);
  EXPECT_GT(pineEarly, 0.6) << "pine should lead the first decades";
  for (int year = 40; year < 200; ++year) ecosystem.step();
  const double pineLate = canopyShare(1), beechLate = canopyShare(0);
  // Pine loses at least 30 points of canopy share to beech (two species: shares sum to 1).
  EXPECT_LT(pineLate, pineEarly - 0.3);
  EXPECT_NEAR(beechLate, 1.0 - pineLate, 1e-12);
}

TEST(Ecosystem, SamePlantsWithOneAndTwoThreads) {
  const Terrain terrain = flat(24, 10.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    Ecosystem ecosystem(
        terrain,
        {test::inEcosystem(test::testSpecies("a", {}), fields, 5.0),
         test::inEcosystem(test::testSpecies("b", {.dispersal = "wind"}), fields, 5.0)},
        settingsWith());
    for (int year = 0; year < 45; ++year) ecosystem.step();
    return ecosystem.state();
  };
  const EcosystemState one = run(1), two = run(2);
  ASSERT_GT(one.plants.size(), 1000u);
  EXPECT_EQ(one.nextId, two.nextId);
  EXPECT_EQ(one.plants.id, two.plants.id);
  EXPECT_EQ(one.plants.east_m, two.plants.east_m);
  EXPECT_EQ(one.plants.height_m, two.plants.height_m);
  EXPECT_EQ(one.plants.light, two.plants.light);
  EXPECT_EQ(one.plants.vigor, two.plants.vigor);
  EXPECT_EQ(one.plants.dbh_m, two.plants.dbh_m);
}

TEST(Ecosystem, SaplingsWaitBelowBreastHeightWhereTheCanopyLayerIsFull) {
  const Terrain terrain = flat(10, 10.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  TestEcology e;
  e.ecologyLines = "light_response = [[0, 1]]";
  Ecosystem ecosystem(terrain, {test::inEcosystem(test::testSpecies("s", e), fields, 200.0)},
                      settingsWith());
  for (int year = 0; year < 30; ++year) ecosystem.step();
  std::vector<int> stems(terrain.grid.cellCount(), 0);
  const Plants& p = ecosystem.plants();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.height_m[i] >= kBreastHeight_m) ++stems[p.cell[i]];
  for (int count : stems) EXPECT_LE(count, ecosystem.stemsPerCell());
  EXPECT_EQ(*std::max_element(stems.begin(), stems.end()), ecosystem.stemsPerCell());
}

}  // namespace
}  // namespace eco
