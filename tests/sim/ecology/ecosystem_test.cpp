#include "sim/ecology/ecosystem.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "ecosystem_support.hpp"
#include "sim/ecology/growth.hpp"
#include "sim/ecology/light_grid.hpp"
#include "sim/ecology/stand_measures.hpp"
#include "sim/ecology/suitability.hpp"
#include "terrain_support.hpp"

namespace eco {
namespace {

using test::TestEcology;

Terrain flat(int cells, double cell_m) {
  return test::analyticTerrain(cells, cells, cell_m, cell_m, [](double, double) { return 500.0; });
}

EcosystemSettings settings() {
  EcosystemSettings s;
  s.seed = 11;
  return s;
}

// A single species on flat, uniform ground spreads from one source as its dispersal kernel
// implies: the seedlings of one year lie at about the kernel's mean distance from the source.
// Further, not nearer: the seed density is spread on a grid of 0.8 kernel means
// (dispersal.hpp), which moves the seeds that fall next to the source out across its block,
// and near the source more seeds fall on one regeneration cell than it takes.
TEST(Ecosystem, SeedlingsFromOneSourceLieAtTheKernelsMeanDistance) {
  const Terrain terrain = flat(81, 5.0);  // 400 m across: 10 mean distances to the edge
  const ConditionFields fields = test::uniformConditions(terrain);
  TestEcology e;
  e.ecologyLines = "light_response = [[0, 1]]";  // shade does not matter here
  e.fecundityPerM2 = 12.0;
  e.germination = 1.0;
  e.dispersalMean_m = 20.0;
  Ecosystem ecosystem(terrain, fields,
                      {test::inEcosystem(test::testSpecies("spreader", e), fields)}, settings());
  const double centre = 200.0;
  ecosystem.plant(0, centre, centre, 60);
  ecosystem.step();
  const Plants& p = ecosystem.plants();
  ASSERT_GT(p.size(), 300u);
  double sum = 0.0;
  for (std::size_t i = 1; i < p.size(); ++i)
    sum += std::hypot(p.east_m[i] - centre, p.north_m[i] - centre);
  const double mean = sum / static_cast<double>(p.size() - 1);
  // Distances are exponential with the kernel's mean: the standard error of the mean of
  // n > 300 is under 0.06 mean.
  EXPECT_GT(mean, 20.0 * 0.92);
  EXPECT_LT(mean, 20.0 * 1.5);
  EXPECT_EQ(ecosystem.bornLastYear()[0], static_cast<int>(p.size() - 1));
}

// An empty map inside a beech forest: the forest's seedlings come in from the edges.
TEST(Ecosystem, TheSurroundingForestSeedsTheMapFromItsEdges) {
  const Terrain terrain = flat(60, 10.0);  // 600 m across
  const ConditionFields fields = test::uniformConditions(terrain);
  EcosystemSpecies beech = test::inEcosystem(test::shippedSpecies("beech"), fields);
  beech.surroundingForestShare = 1.0;
  // Only the nuts that mice carry: the jays' flights of 200 m fill the inner square too
  // within these years, which says nothing of where the seeds come from.
  beech.ecology.life.longDistanceFraction = 0.0;
  Ecosystem ecosystem(terrain, fields, {beech}, settings());
  for (int year = 0; year < 4; ++year) ecosystem.step();  // a mast year among them
  const Plants& p = ecosystem.plants();
  int nearEdge = 0, inner = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double edge = std::min(
        {p.east_m[i] + 5.0, 595.0 - p.east_m[i], p.north_m[i] + 5.0, 595.0 - p.north_m[i]});
    nearEdge += edge < 50.0;
    inner += edge > 200.0;
  }
  // The band within 50 m of the edges is 0.31 of the map, the square 200 m in 0.11.
  EXPECT_GT(nearEdge, 100);
  EXPECT_LT(inner, nearEdge / 20);
}

TEST(Ecosystem, SpeciesExcludedFromTheUpperHalfNeverEstablishesThere) {
  // A slope from 0 m in the south to 1000 m in the north; tolerance ends at 500 m.
  const Terrain terrain = test::analyticTerrain(
      40, 40, 10.0, 10.0, [](double, double north) { return north * 1000.0 / 390.0; });
  ConditionFields fields = test::uniformConditions(terrain);
  TestEcology e;
  e.toleranceLines = "altitude_m = [[0, 1], [490, 1], [500, 0]]";
  e.maturityAge_years = 5;
  Ecosystem ecosystem(terrain, fields,
                      {test::inEcosystem(test::testSpecies("lowland", e), fields, 50.0)},
                      settings());
  for (int year = 0; year < 25; ++year) ecosystem.step();
  const Plants& p = ecosystem.plants();
  ASSERT_GT(p.size(), 500u);
  for (std::size_t i = 0; i < p.size(); ++i)
    EXPECT_LT(ecosystem.groundOf(p, i), 500.0f) << "plant " << p.id[i];
}

// Pine's small seeds take on bare mineral soil and few in a meadow's sward: on open fresh
// ground (a sward over 0.9 of it) a species with a sward establishment of 0.2 gets about
// 0.1 + 0.9 x 0.2 of the seedlings it gets on dry ground, where the grasses leave the soil
// bare (seedbed.hpp). The test species is indifferent to moisture, so only the seedbed
// differs.
TEST(Ecosystem, SmallSeedsTakeOnBareSoilAndFewInASward) {
  const Terrain terrain = flat(100, 2.0);  // 200 m across: 10,000 regeneration cells
  auto bornOn = [&](float moisture) {
    ConditionFields fields = test::uniformConditions(terrain);
    fields.moisture.assign(fields.moisture.size(), moisture);
    EcosystemSpecies species = test::inEcosystem(test::testSpecies("pinelike", {}), fields, 500.0);
    species.ecology.life.swardEstablishment = 0.2;
    Ecosystem ecosystem(terrain, fields, {species}, settings());
    ecosystem.step();
    return ecosystem.bornLastYear()[0];
  };
  const int bare = bornOn(1.0f), sward = bornOn(5.0f);
  // 500 seeds a hectare on 4 m2 cells, half of them germinating: a Poisson mean of 0.1 a
  // cell on bare soil, 0.028 in the sward.
  const double cells = 100.0 * 100.0;
  EXPECT_NEAR(bare, cells * -std::expm1(-0.1), 0.15 * cells * 0.095);
  EXPECT_NEAR(static_cast<double>(sward) / bare, std::expm1(-0.028) / std::expm1(-0.1), 0.06);
}

// The sapling layer as iLand keeps it (ecosystem.hpp): a 2 m regeneration cell holds a young
// plant of each species that reaches it, one of each. With a Poisson mean of 1 seedling a
// cell for each of two species (5,000 seeds a hectare on 4 m2, half of them germinating),
// each takes a cell with p = 1 - exp(-1), independently of the other, so p^2 of the cells
// hold both; a cell taking one seedling of any species would hold both in none.
TEST(Ecosystem, SpeciesArrivingTogetherShareACellOneOfEach) {
  const Terrain terrain = flat(20, 5.0);  // 100 m across: 50 x 50 regeneration cells
  const ConditionFields fields = test::uniformConditions(terrain);
  Ecosystem ecosystem(terrain, fields,
                      {test::inEcosystem(test::testSpecies("a", {}), fields, 5000.0),
                       test::inEcosystem(test::testSpecies("b", {}), fields, 5000.0)},
                      settings());
  ecosystem.step();
  std::vector<std::array<int, 2>> held(50 * 50, {0, 0});
  const Plants& p = ecosystem.plants();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int x = static_cast<int>((p.east_m[i] + 2.5f) / 2.0f);
    const int y = static_cast<int>((p.north_m[i] + 2.5f) / 2.0f);
    ++held[static_cast<std::size_t>(y) * 50 + x][p.species[i]];
  }
  int both = 0;
  for (const std::array<int, 2>& cell : held) {
    EXPECT_LE(cell[0], 1);
    EXPECT_LE(cell[1], 1);
    both += cell[0] == 1 && cell[1] == 1;
  }
  const double taken = -std::expm1(-1.0);
  // The standard deviation of the share of 2,500 cells is under 0.01.
  EXPECT_NEAR(both / 2500.0, taken * taken, 0.04);
}

// A cell takes no more seedlings once one of its young plants has passed breast height; below
// that it takes those of the species it lacks, but no second of one it holds.
TEST(Ecosystem, ACellClosesWhenAYoungPlantPassesBreastHeight) {
  const Terrain terrain = flat(20, 5.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  // Seeds of b fall everywhere in numbers (a Poisson mean of 200 a cell); a has none.
  Ecosystem ecosystem(terrain, fields,
                      {test::inEcosystem(test::testSpecies("a", {}), fields),
                       test::inEcosystem(test::testSpecies("b", {}), fields, 1e6)},
                      settings());
  // Regeneration cells are 2 m squares from -2.5 m: (15.5, 15.5) .. (17.5, 17.5) is one.
  ecosystem.plant(0, 16.5, 16.5, 4);  // a sapling above breast height
  ASSERT_GT(ecosystem.plants().height_m[0], kBreastHeight_m);
  ASSERT_LT(ecosystem.plants().height_m[0], 3.0);
  ecosystem.plantSapling(0, 36.5, 36.5, 0.2, 0, PlantOrigin::Seeded);  // a small seedling
  ecosystem.step();
  auto inCell = [&](double east, double north, int species) {
    int n = 0;
    const Plants& p = ecosystem.plants();
    for (std::size_t i = 0; i < p.size(); ++i)
      n += p.species[i] == species && std::abs(p.east_m[i] - east) < 1.0 &&
           std::abs(p.north_m[i] - north) < 1.0;
    return n;
  };
  EXPECT_EQ(inCell(16.5, 16.5, 1), 0);
  EXPECT_EQ(inCell(36.5, 36.5, 1), 1);
  EXPECT_EQ(inCell(56.5, 56.5, 1), 1);  // an empty cell
  EXPECT_EQ(inCell(36.5, 36.5, 0), 1);
}

// The first young plant of a cell to pass 4 m becomes a tree, and the cell's other seedlings
// and saplings die; planted stock stays, and so do seedlings in the next cell.
TEST(Ecosystem, TheFirstToPassFourMetresClearsItsCell) {
  const Terrain terrain = flat(20, 5.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  TestEcology barren;  // no seeds within these years
  barren.maturityAge_years = 100;
  const std::vector<EcosystemSpecies> species = {
      test::inEcosystem(test::testSpecies("a", barren), fields),
      test::inEcosystem(test::testSpecies("b", barren), fields)};
  // The oldest age at which a grows alone to below 4 m; regeneration cells as above.
  int age = 1;
  for (;; ++age) {
    Ecosystem scratch(terrain, fields, species, settings());
    scratch.plant(0, 16.5, 16.5, age + 1);
    if (scratch.plants().height_m[0] >= kRegenerationHeight_m) break;
  }
  Ecosystem ecosystem(terrain, fields, species, settings());
  ecosystem.plant(0, 16.5, 16.5, age);
  ecosystem.plantSapling(1, 16.0, 17.0, 0.2, 0, PlantOrigin::Seeded);   // the same cell
  ecosystem.plantSapling(1, 17.0, 16.0, 0.2, 0, PlantOrigin::Planted);  // the same cell
  ecosystem.plantSapling(1, 18.5, 16.5, 0.2, 0, PlantOrigin::Seeded);   // the next cell
  int year = 0;
  while (ecosystem.plants().height_m[0] < kRegenerationHeight_m && year < 5) {
    ASSERT_EQ(ecosystem.plants().size(), 4u) << "year " << year;
    ecosystem.step();
    ++year;
  }
  ASSERT_GE(ecosystem.plants().height_m[0], kRegenerationHeight_m);
  const Plants& p = ecosystem.plants();
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(ecosystem.diedLastYear()[1], 1);
  EXPECT_FLOAT_EQ(p.east_m[1], 17.0f);
  EXPECT_EQ(p.origin[1], static_cast<std::uint8_t>(PlantOrigin::Planted));
  EXPECT_FLOAT_EQ(p.east_m[2], 18.5f);
}

// The young plants of the sapling layer (below 4 m) grow as iLand's saplings do: in height,
// with the diameter of the sapling height/diameter ratio from breast height on, and they cast
// no shade. The first to pass 4 m is a tree: a crown in the light grid, whose shade reaches
// the ground.
TEST(Ecosystem, TheSaplingLayerCastsNoShadeAndTreesDo) {
  const Terrain terrain = flat(12, 5.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  TestEcology barren;  // no seeds within these years
  barren.maturityAge_years = 100;
  Ecosystem ecosystem(terrain, fields, {test::inEcosystem(test::testSpecies("a", barren), fields)},
                      settings());
  const LifeHistory& life = ecosystem.species()[0].ecology.life;
  for (double north = 10.5; north < 40.0; north += 1.0)
    for (double east = 10.5; east < 40.0; east += 1.0) ecosystem.plantSapling(0, east, north, 0.3);
  const Plants& p = ecosystem.plants();
  auto tallest = [&] { return *std::max_element(p.height_m.begin(), p.height_m.end()); };
  int polesSeen = 0;
  while (tallest() < kRegenerationHeight_m) {
    ecosystem.step();
    if (tallest() >= kRegenerationHeight_m) break;
    // The light of the last step, through a crowd of 900 plants up to 4 m: the open sky's.
    EXPECT_DOUBLE_EQ(ecosystem.lightAt(25.0, 25.0, 0.0), 1.0) << "year " << ecosystem.year();
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.height_m[i] < kBreastHeight_m) continue;
      ++polesSeen;
      EXPECT_FLOAT_EQ(p.dbh_m[i], static_cast<float>(saplingDiameter(life, p.height_m[i])));
    }
  }
  EXPECT_GT(polesSeen, 100);
  ecosystem.step();  // the trees' first crowns
  EXPECT_LT(ecosystem.lightAt(25.0, 25.0, 0.0), 0.9);
}

// Planted stock may be anything of the sapling layer, from a seedling to heavy nursery stock
// of 3.5 m: below breast height it has no diameter, above it the sapling height/diameter
// ratio's, and it grows as a sapling (no shade) until it passes 4 m.
TEST(Ecosystem, PlantedStockIsASaplingOfItsHeight) {
  const Terrain terrain = flat(12, 5.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  Ecosystem ecosystem(terrain, fields, {test::inEcosystem(test::shippedSpecies("beech"), fields)},
                      settings());
  const LifeHistory& life = ecosystem.species()[0].ecology.life;
  ecosystem.plantSapling(0, 20.0, 20.0, 0.5, 2);
  ecosystem.plantSapling(0, 40.0, 40.0, 3.5, 8);
  ecosystem.plantSapling(0, 30.0, 30.0, 9.0, 8);  // held below 4 m
  const Plants& p = ecosystem.plants();
  EXPECT_EQ(p.dbh_m[0], 0.0f);
  EXPECT_FLOAT_EQ(p.dbh_m[1], static_cast<float>(saplingDiameter(life, 3.5)));
  EXPECT_FLOAT_EQ(p.crownRadius_m[1], static_cast<float>(crownRadiusOf(life, p.dbh_m[1], 3.5)));
  EXPECT_LT(p.height_m[2], kRegenerationHeight_m);
  EXPECT_EQ(p.age_years[1], 8);
  ecosystem.step();
  EXPECT_DOUBLE_EQ(ecosystem.lightAt(40.0, 40.0, 0.0), 1.0);  // a sapling casts no shade
}

TEST(Ecosystem, NoPlantGrowsTallerThanItsSpeciesMaximum) {
  const Terrain terrain = flat(24, 10.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  TestEcology fast;
  fast.maxHeight_m = 12.0;
  Ecosystem ecosystem(terrain, fields,
                      {test::inEcosystem(test::testSpecies("short", fast), fields, 20.0)},
                      settings());
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
  Ecosystem ecosystem(terrain, fields, {test::inEcosystem(test::testSpecies("shade", {}), fields)},
                      settings());
  // Old trees 5 m apart over the western half; the eastern half is open.
  for (double east = 2.5; east < 140.0; east += 5.0)
    for (double north = 2.5; north < 295.0; north += 5.0) ecosystem.plant(0, east, north, 80);
  ecosystem.step();  // builds this year's crowns
  EXPECT_LT(ecosystem.lightAt(70.0, 150.0, 0.0), 0.2);
  EXPECT_GT(ecosystem.lightAt(260.0, 150.0, 0.0), 0.9);
  EXPECT_DOUBLE_EQ(ecosystem.lightAt(70.0, 150.0, 100.0), 1.0);  // above every crown
}

// The shade-tolerant beech lives under a canopy where the light-demanding pine starves:
// under an old beech stand, young pines die of carbon starvation, young beeches of the same
// age keep most of their number.
TEST(Ecosystem, PineStarvesUnderBeechWhereBeechSurvives) {
  const Terrain terrain = flat(20, 10.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  Ecosystem ecosystem(terrain, fields,
                      {test::inEcosystem(test::shippedSpecies("beech"), fields),
                       test::inEcosystem(test::shippedSpecies("pine"), fields)},
                      settings());
  for (double east = 0.0; east < 190.0; east += 8.0)
    for (double north = 0.0; north < 190.0; north += 8.0) ecosystem.plant(0, east, north, 90);
  const std::uint64_t firstYoung = ecosystem.state().nextId;
  for (double east = 4.0; east < 190.0; east += 8.0)
    for (double north = 4.0; north < 190.0; north += 8.0) {
      ecosystem.plant(0, east, north - 2.0, 15);
      ecosystem.plant(1, east, north + 2.0, 15);
    }
  const std::uint64_t lastYoung = ecosystem.state().nextId;
  // The young trees planted here, not the seedlings the stand raises among them.
  auto youngOf = [&](int species) {
    const Plants& p = ecosystem.plants();
    int n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      n += p.species[i] == species && p.id[i] >= firstYoung && p.id[i] < lastYoung;
    return n;
  };
  const int planted = youngOf(0);
  ASSERT_EQ(youngOf(1), planted);
  for (int year = 0; year < 25; ++year) ecosystem.step();
  EXPECT_LT(youngOf(1), 0.2 * planted);
  EXPECT_GT(youngOf(0), 0.5 * planted);
  EXPECT_GT(youngOf(0), 3 * youngOf(1));
}

// Beech planted under a 30-year-old pine stand grows up through it and overtops it between
// 80 and 120 years, while the pines, now among its crowns, decline (the shade-tolerant
// replacing the pioneer, by mechanism; slowly, as it does in real stands).
TEST(Ecosystem, BeechUnderPineOvertopsItAndPineDeclines) {
  const Terrain terrain = flat(20, 5.0);  // 100 m x 100 m
  const ConditionFields fields = test::uniformConditions(terrain);
  Ecosystem ecosystem(terrain, fields,
                      {test::inEcosystem(test::shippedSpecies("beech"), fields),
                       test::inEcosystem(test::shippedSpecies("pine"), fields)},
                      settings());
  for (double north = -1.0; north < 97.0; north += 4.0)
    for (double east = -1.0; east < 97.0; east += 4.0) ecosystem.plant(1, east, north, 30);
  for (double north = 0.0; north < 97.0; north += 2.0)
    for (double east = 0.0; east < 97.0; east += 2.0) ecosystem.plantSapling(0, east, north, 0.3);
  auto measures = [&] { return measureStands(ecosystem.plants(), ecosystem.species(), 1.0); };
  const double pinesAtStart = measures()[1].stemsPerHa;
  std::vector<StandMeasures> at80, at100;
  for (int year = 1; year <= 120; ++year) {
    ecosystem.step();
    if (year == 80) at80 = measures();
    if (year == 100) at100 = measures();
  }
  const std::vector<StandMeasures> at120 = measures();
  EXPECT_LT(at80[0].dominantHeight_m, at80[1].dominantHeight_m);    // still below at 80
  EXPECT_GT(at120[0].dominantHeight_m, at120[1].dominantHeight_m);  // above at 120
  EXPECT_LT(at120[1].stemsPerHa, 0.3 * pinesAtStart);
  EXPECT_LT(at120[1].basalArea_m2PerHa, at100[1].basalArea_m2PerHa);  // pine past its peak
  EXPECT_GT(at120[0].basalArea_m2PerHa, at100[0].basalArea_m2PerHa);
}

// A planted stand thins itself as its trees grow: stems fall and basal area rises, with no
// cap on the number of stems.
TEST(Ecosystem, APlantedStandThinsItself) {
  const Terrain terrain = flat(16, 4.0);  // 64 m x 64 m
  const ConditionFields fields = test::uniformConditions(terrain);
  Ecosystem ecosystem(terrain, fields, {test::inEcosystem(test::shippedSpecies("beech"), fields)},
                      settings());
  for (double north = -1.5; north < 62.0; north += 1.0)
    for (double east = -1.5; east < 62.0; east += 1.0) ecosystem.plantSapling(0, east, north, 0.3);
  const double area_ha = 64.0 * 64.0 / 1e4;
  std::vector<StandMeasures> decades;
  // From 60 years on, when most trees have passed the calipering limit of 10 cm.
  for (int year = 1; year <= 100; ++year) {
    ecosystem.step();
    if (year >= 60 && year % 20 == 0)
      decades.push_back(measureStands(ecosystem.plants(), ecosystem.species(), area_ha)[0]);
  }
  for (std::size_t d = 1; d < decades.size(); ++d) {
    EXPECT_LT(decades[d].stemsPerHa, decades[d - 1].stemsPerHa) << "year " << 60 + 20 * d;
    EXPECT_GT(decades[d].qmd_cm, decades[d - 1].qmd_cm) << "year " << 60 + 20 * d;
  }
  EXPECT_GT(decades.back().basalArea_m2PerHa, 20.0);
  EXPECT_LT(decades.back().basalArea_m2PerHa, 50.0);
}

// Crowding shapes the crown as a forester sees it: in a closed stand the lower branches of a
// beech lose their light and die, so it carries a higher crown base over a longer clear bole
// than a beech of the same age and height standing in the open, which keeps the open-grown
// crown of its species (crown_ratio, iLand's 0.62 for beech) however its own crown shades
// the ground beneath it.
TEST(Ecosystem, ACrowdedTreeHasAHigherCrownBaseThanAnOpenGrownOne) {
  const Terrain terrain =
      test::analyticTerrain(20, 10, 10.0, 10.0, [](double, double) { return 500.0; });
  const ConditionFields fields = test::uniformConditions(terrain);
  Ecosystem ecosystem(terrain, fields, {test::inEcosystem(test::shippedSpecies("beech"), fields)},
                      settings());
  for (double north = 20.0; north < 80.0; north += 5.0)
    for (double east = 10.0; east < 70.0; east += 5.0) ecosystem.plant(0, east, north, 80);
  ecosystem.plant(0, 170.0, 50.0, 80);  // 100 m from the stand
  for (int year = 0; year < 5; ++year) ecosystem.step();
  const Plants& p = ecosystem.plants();
  std::size_t lone = p.size();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.age_years[i] == 85 && p.east_m[i] > 150.0f) lone = i;
  ASSERT_LT(lone, p.size());
  const float height = p.height_m[lone];
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.age_years[i] != 85 || std::abs(p.north_m[i] - 50.0f) > 12.0f ||
        std::abs(p.east_m[i] - 40.0f) > 12.0f)
      continue;  // the stand's inner trees
    EXPECT_NEAR(p.height_m[i], height, 0.15f * height);
    EXPECT_GT(p.crownBase_m[i], p.crownBase_m[lone] + 0.3f * height) << i;
  }
  const double openGrown = 1.0 - test::shippedSpecies("beech").ecology.life.crownRatio;
  EXPECT_NEAR(p.crownBase_m[lone], openGrown * height, 0.05 * height);
}

// Liebig's law of the minimum (the EcoMod paper: "a single inconvenient living condition can
// fully stop the prosperity of some tree"): each condition at beech's zero point, the others
// at their best, lets no seed establish and no planted tree or sapling live 20 years.
TEST(Ecosystem, OneConditionAtItsZeroPointLeavesNoSurvivors) {
  const Terrain terrain = flat(10, 10.0);
  const EcosystemSpecies beech = test::shippedSpecies("beech");
  const ToleranceCurves t = beech.ecology.tolerances(Climate{});
  const ConditionFields best = test::uniformConditions(terrain);
  ASSERT_EQ(combineSuitabilities(conditionSuitabilities(t, best, 0), SuitabilityRule::Minimum),
            1.0);
  // The upper zero point of each curve is its last control point.
  auto zeroOf = [&](Condition c) { return static_cast<float>(t.of(c).points().back().x); };
  struct Case {
    const char* name;
    Field ConditionFields::*field;
    float value;
  };
  const std::vector<Case> cases = {
      {"altitude", &ConditionFields::altitude_m, zeroOf(Condition::Altitude)},
      {"slope", &ConditionFields::slope_deg, zeroOf(Condition::Slope)},
      {"moisture", &ConditionFields::moisture, zeroOf(Condition::Moisture)},
      {"windiness", &ConditionFields::windiness, zeroOf(Condition::Windiness)},
      // Light: the terrain lets through no more than beech's compensation light.
      {"sunniness", &ConditionFields::sunniness,
       static_cast<float>(beech.ecology.lightCompensation())},
  };
  for (const Case& c : cases) {
    ConditionFields fields = best;
    std::fill((fields.*c.field).begin(), (fields.*c.field).end(), c.value);
    Ecosystem ecosystem(terrain, fields, {test::inEcosystem(beech, fields, 5000.0)}, settings());
    for (double at = 5.0; at < 90.0; at += 10.0) {
      ecosystem.plant(0, at, 50.0, 40);
      ecosystem.plantSapling(0, at, 30.0, 0.5);
    }
    int established = 0;
    for (int year = 0; year < 20; ++year) {
      ecosystem.step();
      established += ecosystem.bornLastYear()[0];
    }
    EXPECT_EQ(established, 0) << c.name;
    EXPECT_EQ(ecosystem.plants().size(), 0u) << c.name;
  }
  // And with every condition at its best, the same plants thrive and seedlings come.
  Ecosystem ecosystem(terrain, best, {test::inEcosystem(beech, best, 5000.0)}, settings());
  ecosystem.plant(0, 50.0, 50.0, 40);
  for (int year = 0; year < 20; ++year) ecosystem.step();
  EXPECT_GT(ecosystem.plants().size(), 100u);
}

TEST(Ecosystem, SamePlantsWithOneAndTwoThreads) {
  const Terrain terrain = flat(24, 10.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    Ecosystem ecosystem(
        terrain, fields,
        {test::inEcosystem(test::testSpecies("a", {}), fields, 5.0),
         test::inEcosystem(test::testSpecies("b", {.dispersal = "wind"}), fields, 5.0)},
        settings());
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
  EXPECT_EQ(one.plants.crownBase_m, two.plants.crownBase_m);
  EXPECT_EQ(one.plants.growthFactor, two.plants.growthFactor);
}

// The plants are kept in order of their light column, and of birth within one, however they
// came: planted anywhere, established, or read back from a checkpoint in another order.
TEST(Ecosystem, ThePlantsAreKeptInOrderOfPlace) {
  const Terrain terrain = flat(24, 10.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  Ecosystem ecosystem(terrain, fields, {test::inEcosystem(test::testSpecies("a", {}), fields, 5.0)},
                      settings());
  for (const auto& [east, north] :
       std::vector<std::pair<double, double>>{{200, 200}, {10, 10}, {120, 30}, {11, 11}})
    ecosystem.plant(0, east, north, 20);
  const LightGrid columns(terrain.grid, Field(terrain.grid.cellCount(), 1.0f));
  auto inOrder = [&](const Plants& p) {
    for (std::size_t i = 1; i < p.size(); ++i) {
      const long before = columns.columnAt(p.east_m[i - 1], p.north_m[i - 1]);
      const long here = columns.columnAt(p.east_m[i], p.north_m[i]);
      if (before > here || (before == here && p.id[i - 1] >= p.id[i])) return false;
    }
    return true;
  };
  for (int year = 0; year < 30; ++year) {
    ecosystem.step();
    ASSERT_TRUE(inOrder(ecosystem.plants())) << "year " << ecosystem.year();
  }
  ASSERT_GT(ecosystem.plants().size(), 500u);
  // A state in reverse order is restored in order of place, as it was.
  const EcosystemState kept = ecosystem.state();
  EcosystemState reversed = kept;
  reversed.plants = {};
  for (std::size_t i = kept.plants.size(); i-- > 0;) reversed.plants.appendRow(kept.plants, i);
  ecosystem.restore(std::move(reversed));
  EXPECT_EQ(ecosystem.plants().id, kept.plants.id);
  EXPECT_EQ(ecosystem.plants().height_m, kept.plants.height_m);
}

// Basal area, stems and stand density index of a planted beech plot do not depend on the
// terrain's cell size: light columns, regeneration cells and planting are fixed in metres.
TEST(Ecosystem, AStandDoesNotDependOnTheCellSize) {
  auto grow = [](double cell_m) {
    const int cells = static_cast<int>(std::lround(64.0 / cell_m));
    const Terrain terrain = flat(cells, cell_m);
    const ConditionFields fields = test::uniformConditions(terrain);
    Ecosystem ecosystem(terrain, fields, {test::inEcosystem(test::shippedSpecies("beech"), fields)},
                        settings());
    const double west = -0.5 * cell_m;  // the map's south-west corner
    for (double north = west + 1.0; north < west + 64.0; north += 2.0)
      for (double east = west + 1.0; east < west + 64.0; east += 2.0)
        ecosystem.plantSapling(0, east, north, 0.3);
    std::vector<StandMeasures> at;
    for (int year = 1; year <= 150; ++year) {
      ecosystem.step();
      if (year == 100 || year == 150)
        at.push_back(
            measureStands(ecosystem.plants(), ecosystem.species(), 64.0 * 64.0 / 1e4).back());
    }
    return at;
  };
  const std::vector<StandMeasures> reference = grow(4.0);
  ASSERT_GT(reference[0].basalArea_m2PerHa, 15.0);
  for (double cell : {2.0, 8.0, 16.0}) {
    const std::vector<StandMeasures> other = grow(cell);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_NEAR(other[k].basalArea_m2PerHa, reference[k].basalArea_m2PerHa,
                  0.1 * reference[k].basalArea_m2PerHa)
          << cell << " m, year " << 100 + 50 * k;
      EXPECT_NEAR(other[k].stemsPerHa, reference[k].stemsPerHa, 0.1 * reference[k].stemsPerHa)
          << cell << " m, year " << 100 + 50 * k;
      EXPECT_NEAR(other[k].sdi, reference[k].sdi, 0.1 * reference[k].sdi)
          << cell << " m, year " << 100 + 50 * k;
    }
  }
}

}  // namespace
}  // namespace eco
