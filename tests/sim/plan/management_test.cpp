#include "sim/plan/management.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "ecosystem_support.hpp"
#include "sim/ecology/stand_measures.hpp"

namespace eco {
namespace {

// 100 m x 100 m of level ground in 10 m cells (east and north -5 .. 95 m) with two test
// species "a" and "b", both thriving everywhere, and no plants yet.
struct TwoSpeciesHectare : ::testing::Test {
  Terrain terrain = test::analyticTerrain(10, 10, 10.0, 10.0, [](double, double) { return 50.0; });
  ConditionFields fields = test::uniformConditions(terrain);
  std::vector<EcosystemSpecies> species{test::inEcosystem(test::testSpecies("a", {}), fields),
                                        test::inEcosystem(test::testSpecies("b", {}), fields)};

  static RegionSpec square(double west, double south, double east, double north) {
    RegionSpec r;
    r.kind = RegionSpec::Kind::Polygon;
    r.points = {{west, south}, {east, south}, {east, north}, {west, north}};
    return r;
  }
  static Planting planting(std::vector<SpeciesShare> mix, double spacing_m) {
    Planting p;
    p.mix = std::move(mix);
    p.spacing_m = p.rowSpacing_m = spacing_m;
    return p;
  }
};

TEST_F(TwoSpeciesHectare, PlantedProportionsFollowTheMixWithinBinomialError) {
  Ecosystem ecosystem(terrain, fields, species, {});
  Plan plan;
  plan.planting.push_back(planting({{"a", 0.7}, {"b", 0.3}}, 1.0));
  Management management(plan, ecosystem, 3);
  PlanYear done(2);
  management.plantAtStartOf(1, done, {});
  ASSERT_EQ(ecosystem.plants().size(), 10000u);
  EXPECT_EQ(done.planted[0] + done.planted[1], 10000);
  // 7,000 expected, binomial standard deviation sqrt(10,000 x 0.7 x 0.3) = 46: within 4 of them.
  EXPECT_NEAR(static_cast<double>(done.planted[0]), 7000.0, 4.0 * 46.0);
  for (std::uint8_t origin : ecosystem.plants().origin)
    EXPECT_EQ(origin, static_cast<std::uint8_t>(PlantOrigin::Planted));
  // Nothing is planted in another year.
  PlanYear later(2);
  management.plantAtStartOf(2, later, {});
  EXPECT_EQ(later.planted[0] + later.planted[1], 0);
}

TEST_F(TwoSpeciesHectare, ARowPatternPlantsItsSpeciesRowByRow) {
  Ecosystem ecosystem(terrain, fields, species, {});
  Plan plan;
  Planting rows = planting({}, 2.0);
  rows.rows = {{"a", 1.0}, {"a", 1.0}, {"b", 1.0}};
  plan.planting.push_back(rows);
  PlanYear done(2);
  Management(plan, ecosystem, 3).plantAtStartOf(1, done, {});
  const Plants& p = ecosystem.plants();
  ASSERT_EQ(p.size(), 2500u);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int row = static_cast<int>(std::lround((p.north_m[i] + 5.0) / 2.0 - 0.5));
    EXPECT_EQ(p.species[i], row % 3 == 2 ? 1 : 0);
  }
}

TEST_F(TwoSpeciesHectare, NothingEstablishesOrIsPlantedWhereTheLandIsKeptOpen) {
  std::vector<EcosystemSpecies> seeded = species;
  seeded[0].seedRainPerHaPerYear = 5e4;  // every regeneration cell gets seed
  Ecosystem ecosystem(terrain, fields, seeded, {});
  Plan plan;
  // "b" planted on the western half; "a" seeds itself wherever a regeneration cell is free.
  plan.planting.push_back(planting({{"b", 1.0}}, 2.0));
  plan.planting.back().region = square(-5, -5, 45, 95);
  Exclusion ride;
  ride.region.kind = RegionSpec::Kind::Line;
  ride.region.points = {{-5, 45}, {95, 45}};
  ride.region.buffer_m = 4.0;  // a ride 8 m wide across the map
  plan.exclusions.push_back(ride);
  Exclusion meadow;
  meadow.region = square(59, 59, 89, 89);
  plan.exclusions.push_back(meadow);
  Management management(plan, ecosystem, 3);
  PlanYear done(2);
  management.plantAtStartOf(1, done, {});
  EXPECT_EQ(done.planted[1], 25 * 50 - 4 * 25);  // the ride takes 4 of the 50 rows
  for (int year = 0; year < 8; ++year) ecosystem.step();
  const Plants& p = ecosystem.plants();
  std::size_t seedlings = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    seedlings += p.species[i] == 0;
    const bool inRide = std::abs(p.north_m[i] - 45.0) <= 4.0;
    const bool inMeadow =
        p.east_m[i] > 59 && p.east_m[i] < 89 && p.north_m[i] > 59 && p.north_m[i] < 89;
    EXPECT_FALSE(inRide || inMeadow) << p.east_m[i] << ", " << p.north_m[i];
  }
  EXPECT_GT(seedlings, 500u);  // the rest of the map did fill with seedlings
}

TEST_F(TwoSpeciesHectare, PlantedStockDiesInItsFirstYearWhereAConditionRulesItOut) {
  // "a" cannot live on the western half.
  std::vector<EcosystemSpecies> halfRuledOut = species;
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 5; ++x) halfRuledOut[0].suitability[terrain.grid.index(x, y)] = 0.0f;
  for (bool check : {true, false}) {
    Ecosystem ecosystem(terrain, fields, halfRuledOut, {});
    Plan plan;
    plan.planting.push_back(planting({{"a", 1.0}}, 2.0));
    plan.planting.back().survivalCheck = check;
    std::vector<std::string> warnings;
    PlanYear done(2);
    Management(plan, ecosystem, 3).plantAtStartOf(1, done, [&](const std::string& w) {
      warnings.push_back(w);
    });
    ASSERT_EQ(done.planted[0], 2500);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("1250 of 2500 planted a stand where a condition rules a out"),
              std::string::npos);
    ecosystem.step();
    if (check) {
      EXPECT_GE(ecosystem.plantedDiedLastYear()[0], 1250);  // and the east's ordinary deaths
      EXPECT_LT(ecosystem.plantedDiedLastYear()[0], 1300);
      for (float east : ecosystem.plants().east_m) EXPECT_GT(east, 45.0f);
    } else {
      EXPECT_LT(ecosystem.plantedDiedLastYear()[0], 50);  // by the ordinary risks only
    }
  }
}

// Trees of many sizes: the thinning takes the smallest (or largest) first and stops as soon as
// the region is at or below its target, so it ends within one tree's basal area of it.
TEST_F(TwoSpeciesHectare, ThinningReachesItsTargetWithinOneTreesBasalArea) {
  for (ThinningMethod method : {ThinningMethod::FromBelow, ThinningMethod::FromAbove}) {
    Ecosystem ecosystem(terrain, fields, species, {});
    for (int k = 0; k < 400; ++k)
      ecosystem.plant(k % 2, -3.0 + (k % 20) * 4.9, -3.0 + (k / 20) * 4.9, 30 + (k * 37) % 90);
    Plan plan;
    Thinning t;
    t.region = square(-5, -5, 45, 95);  // the western half
    t.fromYear = 1;
    t.method = method;
    t.targetBasalArea_m2PerHa = 20.0;
    plan.thinning.push_back(t);
    Management management(plan, ecosystem, 3);
    auto regionBasalArea = [&](double& smallest, double& largest) {
      double sum = 0.0;
      smallest = 1e9, largest = 0.0;
      const Plants& p = ecosystem.plants();
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.east_m[i] < 45.0f && p.dbh_m[i] >= kMeasuredDbh_m) {
          sum += basalAreaOf(p.dbh_m[i]);
          smallest = std::min<double>(smallest, p.dbh_m[i]);
          largest = std::max<double>(largest, p.dbh_m[i]);
        }
      return sum / 0.5;  // per ha: the region holds 50 cells of 100 m2
    };
    double smallest = 0, largest = 0;
    ASSERT_GT(regionBasalArea(smallest, largest), 30.0);
    const std::size_t before = ecosystem.plants().size();
    PlanYear done(2);
    management.thinAtEndOf(1, done);
    const std::size_t removed = static_cast<std::size_t>(done.removed[0] + done.removed[1]);
    ASSERT_GT(removed, 0u);
    EXPECT_EQ(ecosystem.plants().size(), before - removed);
    ASSERT_EQ(done.removedPlants.size(), removed);
    double left = 0, right = 0;
    const double after = regionBasalArea(left, right);
    double lastRemoved = 0.0, removedMin = 1e9, removedMax = 0.0;
    for (float dbh : done.removedPlants.dbh_m) {
      removedMin = std::min<double>(removedMin, dbh);
      removedMax = std::max<double>(removedMax, dbh);
    }
    lastRemoved = method == ThinningMethod::FromBelow ? removedMax : removedMin;
    EXPECT_LE(after, 20.0);
    EXPECT_GT(after, 20.0 - basalAreaOf(lastRemoved) / 0.5);
    if (method == ThinningMethod::FromBelow)
      EXPECT_LE(removedMax, left);  // every tree left is at least as thick as those taken
    else
      EXPECT_GE(removedMin, right);
    for (float east : done.removedPlants.east_m) EXPECT_LT(east, 45.0f);
    EXPECT_GT(done.removedVolume_m3[0] + done.removedVolume_m3[1], 0.0);
  }
}

TEST_F(TwoSpeciesHectare, ThinningToAStemNumberAndRemovingASpecies) {
  Ecosystem ecosystem(terrain, fields, species, {});
  for (int k = 0; k < 400; ++k)
    ecosystem.plant(k % 2, -4.0 + (k % 20) * 4.9, -4.0 + (k / 20) * 4.9, 30 + (k * 37) % 30);
  Plan plan;
  Thinning stems;
  stems.fromYear = 1;
  stems.targetStemsPerHa = 300.0;
  plan.thinning.push_back(stems);
  Thinning nurse;
  nurse.fromYear = 2;
  nurse.method = ThinningMethod::RemoveSpecies;
  nurse.species = {"b"};
  plan.thinning.push_back(nurse);
  Management management(plan, ecosystem, 3);
  PlanYear first(2);
  management.thinAtEndOf(1, first);
  EXPECT_EQ(ecosystem.plants().size(), 300u);
  PlanYear second(2);
  management.thinAtEndOf(2, second);
  EXPECT_EQ(second.removed[0], 0);
  for (std::uint8_t s : ecosystem.plants().species) EXPECT_EQ(s, 0);
}

TEST_F(TwoSpeciesHectare, ThePlanMapShowsEachRuleWhereItApplies) {
  Ecosystem ecosystem(terrain, fields, species, {});
  Plan plan;
  Planting stand = planting({{"a", 1.0}}, 2.0);
  stand.region = square(-5, -5, 45, 95);
  plan.planting.push_back(stand);
  Exclusion open;
  open.region = square(20, 20, 40, 40);
  plan.exclusions.push_back(open);
  const Field map = Management(plan, ecosystem, 3).planMap();
  const Grid& g = terrain.grid;
  EXPECT_EQ(map[g.index(0, 0)], 3.0f);  // planted
  EXPECT_EQ(map[g.index(3, 6)], 4.0f);  // east 30, north 30: kept open
  EXPECT_EQ(map[g.index(8, 0)], 0.0f);  // nothing
}

// A forest too far off to seed the map would be silently useless: it is refused.
TEST_F(TwoSpeciesHectare, ASeedSourceBeyondTheKernelsReachIsAnError) {
  Ecosystem ecosystem(terrain, fields, species, {});
  Plan plan;
  SeedSource far;
  far.mix = {{"a", 1.0}};
  far.region = square(-3000, 0, -2000, 100);  // 2 km west; "a" flies 20 m on average
  far.region.where = {"s.toml", 12, "seed_source[0].polygon"};
  plan.seedSources.push_back(far);
  try {
    Management m(plan, ecosystem, 3);
    FAIL() << "a seed source out of reach was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 12);
    EXPECT_NE(std::string(e.what()).find("farther from the map than its seeds fly"),
              std::string::npos);
  }
  plan.seedSources[0].region = square(-60, 0, -6, 100);  // just west of the map
  EXPECT_NO_THROW(Management(plan, ecosystem, 3));
}

TEST_F(TwoSpeciesHectare, PlanSpeciesMustBeTheScenarios) {
  Ecosystem ecosystem(terrain, fields, species, {});
  Plan plan;
  plan.planting.push_back(planting({{"c", 1.0, {"s.toml", 9, "planting[0].species"}}}, 2.0));
  try {
    Management m(plan, ecosystem, 3);
    FAIL() << "an unknown species was planted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 9);
    EXPECT_NE(std::string(e.what()).find("no species 'c' in the scenario"), std::string::npos);
  }
}

}  // namespace
}  // namespace eco
