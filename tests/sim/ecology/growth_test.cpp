#include "sim/ecology/growth.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "sim/ecology/light_grid.hpp"

namespace eco {
namespace {

// Beech's allometries (iLand's species table) on a 40 m Chapman-Richards height curve.
LifeHistory life() {
  LifeHistory h;
  h.maxAge_years = 200;
  h.height_m = {40.0, 0.014, 1.27};
  h.foliage = {0.021708, 1.7};
  h.stem = {0.22225, 2.2503739};
  h.branches = {0.022, 2.3};
  h.coarseRoots = {0.018, 2.32};
  h.specificLeafArea = 11.0;
  h.crownDiameterSilva = {0.5856485, 0.4298499, -0.003455, -0.3238132};
  h.lightUseEfficiency = 1.5;
  h.intrinsicSurvival = 0.01;
  h.stressMortality = 1.39;
  h.fecundity_m2 = 40.0;
  h.nonMastFraction = 0.3;
  return h;
}

TEST(Growth, StemVolumeAndCrownFollowTheirAllometries) {
  const LifeHistory h = life();
  EXPECT_NEAR(stemVolume(h, 0.3, 25.0), 0.45 * std::numbers::pi / 4 * 0.09 * 25.0, 1e-12);
  // SILVA's crown diameter of a 30 cm, 25 m beech.
  const double cd = std::exp(0.5856485 + 0.4298499 * std::log(30.0) - 0.003455 * 25.0 -
                             0.3238132 * std::log(25.0 / 30.0));
  EXPECT_NEAR(crownRadiusOf(h, 0.3, 25.0), cd / 2.0, kGrowthPrecision * cd);
  EXPECT_GT(cd, 6.0);  // a stand-grown beech's crown is some 6-10 m across
  EXPECT_LT(cd, 10.0);
  // A young plant's crown is no wider than half its height.
  EXPECT_DOUBLE_EQ(crownRadiusOf(h, 0.0, 0.8), 0.4);
  // Below breast height the function is held at 1 cm and 1.3 m: its limit for seedlings.
  const double limit = seedlingCrownRadiusLimit(h);
  EXPECT_NEAR(limit, 0.5 * std::exp(0.5856485 - 0.003455 * 1.3 - 0.3238132 * std::log(1.3)),
              kGrowthPrecision * limit);
  for (double height : {0.05, 0.4, 0.8, 1.2, 1.29})
    EXPECT_EQ(crownRadiusOf(h, 0.0, height), std::min(limit, 0.5 * height)) << height;
  // Without shade leaves the foliage spreads at the specific leaf area, as in iLand.
  const CrownFoliage foliage = crownFoliage(h, 0.3, 25.0, 1.0);
  const double allometric = 0.021708 * std::pow(30.0, 1.7);
  EXPECT_NEAR(foliage.foliage_kg, allometric, kGrowthPrecision * allometric);
  EXPECT_NEAR(foliage.leafArea_m2, 11.0 * foliage.foliage_kg, 1e-9);
  EXPECT_NEAR(crownFoliage(h, 0.3, 25.0, 0.1).leafArea_m2, foliage.leafArea_m2, 1e-9);
}

// Sun and shade leaves: the layers of a crown are built in the light they get, so the same
// foliage spreads into more leaf area, more so under a darker top; the mass stays the
// allometry's. Analytic: m(L) = (r L + (1 - r) I0 (1 - exp(-k L)) / k) / SLA per m2.
TEST(Growth, ShadeLeavesSpreadTheSameFoliageOverMoreLeafArea) {
  LifeHistory h = life();
  h.shadeLeafMassRatio = 0.4;
  const double radius = crownRadiusOf(h, 0.3, 25.0);
  const double projection = std::numbers::pi * radius * radius;
  auto massOf = [&](double leafArea, double top) {
    const double lai = leafArea / projection;
    return projection / h.specificLeafArea *
           (0.4 * lai + 0.6 * top * (1.0 - std::exp(-kLeafExtinction * lai)) / kLeafExtinction);
  };
  const double allometric = 0.021708 * std::pow(30.0, 1.7);
  double last = 11.0 * allometric;  // sun leaves alone
  for (double top : {1.0, 0.5, 0.1, 0.0}) {
    const CrownFoliage foliage = crownFoliage(h, 0.3, 25.0, top);
    EXPECT_NEAR(foliage.foliage_kg, allometric, kGrowthPrecision * allometric) << top;
    EXPECT_NEAR(massOf(foliage.leafArea_m2, top), allometric, kGrowthPrecision * allometric) << top;
    EXPECT_GT(foliage.leafArea_m2, last) << top;
    last = foliage.leafArea_m2;
  }
  // In darkness every leaf is a shade leaf: 1 / 0.4 of the sun leaves' area.
  EXPECT_NEAR(crownFoliage(h, 0.3, 25.0, 0.0).leafArea_m2, 11.0 * allometric / 0.4,
              kGrowthPrecision * 11.0 * allometric / 0.4);
  EXPECT_DOUBLE_EQ(leafMassShare(h, 0.0), 0.4);
  EXPECT_DOUBLE_EQ(leafMassShare(h, 0.5), 0.7);
  EXPECT_DOUBLE_EQ(leafMassShare(h, 2.0), 1.0);
}

TEST(Growth, ACrownHoldsNoMoreLeavesThanItsProjectionCanLight) {
  LifeHistory h = life();
  // At the deepest leaf the open sky's light has fallen to the compensation light.
  EXPECT_NEAR(std::exp(-kLeafExtinction * maxCrownLeafAreaIndex(h)), leafCompensationLight(h),
              1e-12);
  // Beech's foliage stays below it; a foliage allometry four times as heavy reaches it.
  const double radius = crownRadiusOf(h, 0.3, 25.0);
  const double projection = std::numbers::pi * radius * radius;
  EXPECT_LT(crownFoliage(h, 0.3, 25.0, 1.0).leafArea_m2, maxCrownLeafAreaIndex(h) * projection);
  h.foliage.a *= 4.0;
  const CrownFoliage capped = crownFoliage(h, 0.3, 25.0, 1.0);
  EXPECT_NEAR(capped.leafArea_m2, maxCrownLeafAreaIndex(h) * projection, 1e-9);
  // It holds (and pays for) only the leaves it can light.
  EXPECT_NEAR(capped.foliage_kg, capped.leafArea_m2 / h.specificLeafArea, 1e-9);
  // The species' limit worked out once gives the same foliage, to the bit, as worked out
  // per crown, capped or not, in any light.
  const FoliageLimit limit = foliageLimitOf(h);
  EXPECT_EQ(limit.leafAreaIndex, maxCrownLeafAreaIndex(h));
  EXPECT_NEAR(limit.absorbedShare, 1.0 - leafCompensationLight(h), 1e-12);
  for (double dbh : {0.01, 0.3, 0.8})
    for (double top : {0.0, 0.4, 1.0}) {
      const CrownFoliage once = crownFoliage(h, limit, dbh, crownRadiusOf(h, dbh, 25.0), top);
      EXPECT_EQ(once.leafArea_m2, crownFoliage(h, dbh, 25.0, top).leafArea_m2);
      EXPECT_EQ(once.foliage_kg, crownFoliage(h, dbh, 25.0, top).foliage_kg);
    }
  // A more efficient leaf pays its way deeper in the crown.
  LifeHistory efficient = life();
  efficient.lightUseEfficiency *= 2.0;
  EXPECT_NEAR(maxCrownLeafAreaIndex(efficient) - maxCrownLeafAreaIndex(life()),
              std::log(2.0) / kLeafExtinction, 1e-12);
}

TEST(Growth, WoodyBiomassInvertsToTheDiameter) {
  const LifeHistory h = life();
  for (double dbh : {0.011, 0.05, 0.2, 0.45, 0.9}) {
    EXPECT_NEAR(diameterOfWoodyBiomass(h, woodyBiomass(h, dbh)), dbh, kGrowthPrecision * dbh)
        << dbh;
    // From last year's diameter, as a growing tree asks.
    EXPECT_NEAR(diameterOfWoodyBiomass(h, woodyBiomass(h, dbh), 0.97 * dbh), dbh,
                kGrowthPrecision * dbh);
  }
  EXPECT_EQ(diameterOfWoodyBiomass(h, 0.0), 0.0);
  const double wood_kg = 0.22225 * std::pow(30.0, 2.2503739) + 0.022 * std::pow(30.0, 2.3) +
                         0.018 * std::pow(30.0, 2.32);
  EXPECT_NEAR(woodyBiomass(h, 0.3), wood_kg, kGrowthPrecision * wood_kg);
}

TEST(Growth, TheCrownsUpkeepIsItsTurnoverAndALeafAtTheCompensationLightJustPaysIt) {
  const LifeHistory h = life();
  // One leaf turnover a year, and fine roots of 0.75 the foliage renewed once a year.
  EXPECT_NEAR(crownUpkeep(h, 10.0), 10.0 * (1.0 + 0.75), 1e-12);
  const double light = leafCompensationLight(h);
  const double sunLeaf_kg = 1.0 / h.specificLeafArea;  // a m2 of sun leaves
  EXPECT_NEAR(h.lightUseEfficiency * kLeafExtinction * light, crownUpkeep(h, sunLeaf_kg), 1e-12);
  EXPECT_GT(light, 0.0);
  EXPECT_LT(light, 1.0);
  // A shade leaf, thinner, pays its way in less light: at the compensation light it makes
  // exactly the upkeep of a leaf built in that light.
  LifeHistory shade = h;
  shade.shadeLeafMassRatio = 0.4;
  const double shadeLight = leafCompensationLight(shade);
  EXPECT_NEAR(shade.lightUseEfficiency * kLeafExtinction * shadeLight,
              crownUpkeep(shade, sunLeaf_kg * leafMassShare(shade, shadeLight)), 1e-12);
  EXPECT_LT(shadeLight, 0.5 * light);
}

TEST(Growth, WoodIsWhatProductionLeavesAfterTheUpkeep) {
  const LifeHistory h = life();
  const double dbh = 0.2, height = 20.0;
  const double leaves = crownFoliage(h, dbh, height, 1.0).foliage_kg;  // kg of foliage
  const double absorbed = 0.6 * h.specificLeafArea * leaves;
  const TreeYear year = growTree(h, dbh, height, leaves, absorbed, {});
  EXPECT_NEAR(year.production_kg, 1.5 * absorbed, 1e-12);
  EXPECT_NEAR(year.upkeep_kg, crownUpkeep(h, leaves), 1e-12);
  EXPECT_NEAR(woodyBiomass(h, year.dbh_m) - woodyBiomass(h, dbh),
              year.production_kg - year.upkeep_kg, kGrowthPrecision * woodyBiomass(h, dbh));
  EXPECT_EQ(year.carbonDeficit(), 0.0);
  EXPECT_GT(year.height_m, height);
  // The site and the individual scale production; light enters only as absorbed light.
  const TreeYear poorSite = growTree(h, dbh, height, leaves, absorbed, {.suitability = 0.5});
  EXPECT_NEAR(poorSite.production_kg, 0.5 * year.production_kg, 1e-12);
  // Making less than the upkeep: no growth, and the missing share is the carbon deficit.
  const double starving = 0.25 * crownUpkeep(h, leaves) / h.lightUseEfficiency;
  const TreeYear hungry = growTree(h, dbh, height, leaves, starving, {});
  EXPECT_EQ(hungry.dbh_m, dbh);
  EXPECT_EQ(hungry.height_m, height);
  EXPECT_NEAR(hungry.carbonDeficit(), 0.75, 1e-12);
  EXPECT_EQ(growTree(h, dbh, height, leaves, 0.0, {}).carbonDeficit(), 1.0);
}

TEST(Growth, HeightFollowsThePotentialNoFasterThanTheNewWoodCarries) {
  const LifeHistory h = life();
  const double dbh = 0.25, height = 25.0;
  const double leaves = crownFoliage(h, dbh, height, 1.0).foliage_kg;
  const double leafArea = h.specificLeafArea * leaves;
  const TreeYear open = growTree(h, dbh, height, leaves, 0.7 * leafArea, {});
  EXPECT_NEAR(open.height_m - height, potentialHeightIncrement(h, height), 1e-12);
  EXPECT_NEAR(potentialHeightIncrement(h, h.height_m.at(30.0)),
              h.height_m.at(31.0) - h.height_m.at(30.0), kGrowthPrecision * h.height_m.at(31.0));
  // Little wood: the increment is capped by the slenderness a stem can carry.
  const double barely = 1.02 * crownUpkeep(h, leaves) / h.lightUseEfficiency;
  const TreeYear thin = growTree(h, dbh, height, leaves, barely, {.lightResponse = 0.9});
  EXPECT_NEAR(thin.height_m - height, h.maxHeightDiameter * (thin.dbh_m - dbh), 1e-9);
  // A suppressed tree puts its little wood into height: it grows more slender.
  const TreeYear shaded = growTree(h, dbh, height, leaves, 0.25 * leafArea, {.lightResponse = 0.6});
  EXPECT_GT((shaded.height_m - height) / (shaded.dbh_m - dbh),
            (open.height_m - height) / (open.dbh_m - dbh));
  // Nothing passes the species' maximum height.
  EXPECT_EQ(growTree(h, 0.8, 40.0, crownFoliage(h, 0.8, 40.0, 1.0).foliage_kg, 1e4, {}).height_m,
            40.0);
}

TEST(Growth, AgingIsILandsFunctionOfRelativeHeightAndAge) {
  LifeHistory h = life();                     // 40 m at most, 200 years
  EXPECT_EQ(agingFactor(h, 30.0, 100), 1.0);  // no aging unless the species has it
  h.aging = {0.5, 2.0};
  // x is 1 - the harmonic mean of the distances from the maxima: a seedling has x = 0.
  EXPECT_NEAR(agingFactor(h, 0.0, 0), 1.0, 1e-12);
  // At two thirds of the height and age 0, x = 1 - 2 / (3 + 1) = 0.5: half the production.
  EXPECT_NEAR(agingFactor(h, 40.0 * 2.0 / 3.0, 0), 0.5, 1e-12);
  // Height and age enter alike: half the maximum of each, x = 0.5.
  EXPECT_NEAR(agingFactor(h, 20.0, 100), 0.5, 1e-12);
  // iLand's pine (x / 1)^2.5 at x = 0.5.
  h.aging = {1.0, 2.5};
  EXPECT_NEAR(agingFactor(h, 20.0, 100), 1.0 / (1.0 + std::pow(0.5, 2.5)), kGrowthPrecision);
  // At either maximum x = 1 (pine's production halves there), and past them it stays so.
  EXPECT_NEAR(agingFactor(h, 40.0, 10), 0.5, 1e-5);
  EXPECT_NEAR(agingFactor(h, 45.0, 300), 0.5, 1e-5);
}

TEST(Growth, AgingScalesProductionNotUpkeepOrTheHeightCurve) {
  const LifeHistory h = life();
  const double dbh = 0.3, height = 25.0;
  const double leaves = crownFoliage(h, dbh, height, 1.0).foliage_kg;
  const double absorbed = 3.0 * crownUpkeep(h, leaves) / h.lightUseEfficiency;
  const TreeYear young = growTree(h, dbh, height, leaves, absorbed, {});
  const TreeYear old = growTree(h, dbh, height, leaves, absorbed, {.aging = 0.5});
  EXPECT_NEAR(old.production_kg, 0.5 * young.production_kg, 1e-9);
  EXPECT_EQ(old.upkeep_kg, young.upkeep_kg);
  EXPECT_LT(old.dbh_m, young.dbh_m);
  // Saplings and the potential height increment know nothing of it.
  EXPECT_EQ(growSapling(h, 0.5, {.aging = 0.1}).height_m, growSapling(h, 0.5, {}).height_m);
}

TEST(Growth, SaplingsGrowInHeightAsLightAndSiteAllow) {
  const LifeHistory h = life();
  const double potential = potentialHeightIncrement(h, 0.5);
  const SaplingYear full = growSapling(h, 0.5, {});
  EXPECT_NEAR(full.height_m - 0.5, potential, 1e-12);
  EXPECT_FALSE(full.poor);
  const SaplingYear shade = growSapling(h, 0.5, {.suitability = 0.5, .lightResponse = 0.5});
  EXPECT_NEAR(shade.height_m - 0.5, 0.25 * potential, 1e-12);
  EXPECT_TRUE(growSapling(h, 0.5, {.lightResponse = 0.04}).poor);  // below the 5 % threshold
  EXPECT_NEAR(saplingDiameter(h, 1.3), 1.3 / h.saplingHeightDiameter, 1e-12);
}

TEST(Growth, MortalityIsIntrinsicPlusCarbonStarvation) {
  const LifeHistory h = life();
  // 1 % of a cohort reaches the maximum age, and none passes it.
  EXPECT_NEAR(std::pow(1.0 - treeMortality(h, 50, 0.0), 200), 0.01, 1e-12);
  EXPECT_EQ(treeMortality(h, 200, 0.0), 1.0);
  // iLand's stress hazard 1 - exp(-probStress x deficit).
  EXPECT_NEAR(treeMortality(h, 50, 1.0), intrinsicMortality(h) + 1.0 - std::exp(-1.39), 1e-12);
  EXPECT_NEAR(treeMortality(h, 50, 0.5), intrinsicMortality(h) + 1.0 - std::exp(-0.695), 1e-12);
  // The starvation part alone: none without a deficit, and a deficit counts up to all.
  EXPECT_EQ(starvationMortality(h, 0.0), 0.0);
  EXPECT_EQ(starvationMortality(h, -0.3), 0.0);
  EXPECT_NEAR(starvationMortality(h, 0.5), 1.0 - std::exp(-0.695), 1e-15);
  EXPECT_EQ(starvationMortality(h, 3.0), starvationMortality(h, 1.0));
  EXPECT_EQ(treeMortality(h, 50, 0.5), intrinsicMortality(h) + starvationMortality(h, 0.5));
}

TEST(Growth, SeedsScaleWithCrownAreaMastYearsAndLight) {
  const LifeHistory h = life();
  EXPECT_NEAR(seedProduction(h, 2.0, true, 1.0), 40.0 * std::numbers::pi * 4.0, 1e-9);
  EXPECT_NEAR(seedProduction(h, 4.0, true, 1.0), 4.0 * seedProduction(h, 2.0, true, 1.0), 1e-9);
  EXPECT_NEAR(seedProduction(h, 2.0, false, 1.0), 0.3 * seedProduction(h, 2.0, true, 1.0), 1e-9);
  EXPECT_NEAR(seedProduction(h, 2.0, true, 0.5), 0.5 * seedProduction(h, 2.0, true, 1.0), 1e-9);
}

}  // namespace
}  // namespace eco
