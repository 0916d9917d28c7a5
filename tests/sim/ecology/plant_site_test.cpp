#include "sim/ecology/plant_site.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "ecosystem_support.hpp"
#include "sim/conditions/windiness.hpp"
#include "terrain_support.hpp"

namespace eco {
namespace {

Terrain flat(int cells, double cell_m) {
  return test::analyticTerrain(cells, cells, cell_m, cell_m, [](double, double) { return 500.0; });
}

EcosystemSettings settings() {
  EcosystemSettings s;
  s.seed = 5;
  s.windFrom_deg = 270.0;  // from the west: it blows east
  return s;
}

// A closed stand of old trees 5 m apart over the western half of a 300 m square (its
// eastern edge at 140 m), the eastern half open.
struct HalfForest : ::testing::Test {
  Terrain terrain = flat(30, 10.0);
  ConditionFields fields = test::uniformConditions(terrain);
  Ecosystem ecosystem{
      terrain, fields, {test::inEcosystem(test::testSpecies("shade", {}), fields)}, settings()};
  void SetUp() override {
    for (double east = 2.5; east < 140.0; east += 5.0)
      for (double north = 2.5; north < 295.0; north += 5.0) ecosystem.plant(0, east, north, 80);
  }
  // The site of the planted tree nearest a position (not a seedling of the year).
  PlantSite siteNear(double east, double north) {
    const Plants& p = ecosystem.plants();
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < p.size(); ++i)
      if (p.age_years[i] >= 80 &&
          std::hypot(p.east_m[i] - east, p.north_m[i] - north) <
              std::hypot(p.east_m[nearest] - east, p.north_m[nearest] - north))
        nearest = i;
    Plants one;
    one.appendRow(p, nearest);
    return ecosystem.sitesOf(one)[0];
  }
};

TEST_F(HalfForest, BeforeTheFirstYearEverySiteIsNeutral) {
  const PlantSite site = siteNear(137.5, 150.0);
  EXPECT_EQ(site.light, glm::vec2(0.0f));
  EXPECT_EQ(site.wind, glm::vec2(0.0f));
}

// A tree at the edge gets its light from the clearing: its light points east, about as much
// as light from one half of the sky (0.65 for eight directions); deep in the stand the light
// comes evenly from every side.
TEST_F(HalfForest, AnEdgeTreesLightComesFromTheClearing) {
  ecosystem.step();  // builds this year's crowns
  const PlantSite edge = siteNear(137.5, 150.0);
  EXPECT_GT(edge.light.x, 0.45f);
  EXPECT_NEAR(edge.light.y, 0.0f, 0.05f);
  EXPECT_LE(glm::length(edge.light), 1.0f);
  const PlantSite inside = siteNear(67.5, 150.0);
  EXPECT_LT(glm::length(inside.light), 0.1f);
  // On open level ground there is no wind exposure whatever the wind (windiness 0.3).
  EXPECT_EQ(edge.wind, glm::vec2(0.0f));
}

TEST(PlantSite, ALoneTreeOnOpenGroundHasEvenLight) {
  const Terrain terrain = flat(20, 10.0);
  const ConditionFields fields = test::uniformConditions(terrain);
  Ecosystem ecosystem(terrain, fields, {test::inEcosystem(test::testSpecies("t", {}), fields)},
                      settings());
  ecosystem.plant(0, 100.0, 100.0, 60);
  ecosystem.step();
  Plants one;
  one.appendRow(ecosystem.plants(), 0);
  EXPECT_LT(glm::length(ecosystem.sitesOf(one)[0].light), 1e-6f);
}

TEST(PlantSite, ExposureRescalesWindinessAboveOpenLevelGround) {
  EXPECT_EQ(windExposure(kOpenGroundWindiness), 0.0);
  EXPECT_EQ(windExposure(0.1), 0.0);  // a lee
  EXPECT_DOUBLE_EQ(windExposure(1.0), 1.0);
  EXPECT_NEAR(windExposure(0.65), 0.5, 1e-12);
  EXPECT_EQ(windExposure(std::nan("")), 0.0);  // outside the landscape
}

// A ridge's trees get the prevailing wind's direction times its exposure, a sheltered
// valley's none; below breast height nothing is shaped.
TEST(PlantSite, TheWindOfARidgeAndOfAValley) {
  const Terrain terrain = flat(10, 10.0);
  ConditionFields fields = test::uniformConditions(terrain);
  const long ridge = terrain.grid.cellAt(20.0, 50.0), valley = terrain.grid.cellAt(70.0, 50.0);
  fields.windiness[static_cast<std::size_t>(ridge)] = 0.93f;
  fields.windiness[static_cast<std::size_t>(valley)] = 0.1f;
  LightGrid light(terrain.grid, Field(terrain.grid.cellCount(), 1.0f));
  light.compute(std::vector<CrownShape>{});
  Plants p;
  p.resize(3);
  const float east[] = {20.0f, 70.0f, 20.0f}, height[] = {12.0f, 12.0f, 1.0f};
  for (std::size_t i = 0; i < 3; ++i) {
    p.east_m[i] = east[i], p.north_m[i] = 50.0f, p.height_m[i] = height[i];
    p.crownRadius_m[i] = 2.0f;
  }
  const std::vector<PlantSite> sites = plantSites(p, light, terrain.grid, fields.windiness, 225.0);
  // From the south-west: it blows toward the north-east.
  const float exposure = static_cast<float>(windExposure(0.93));
  EXPECT_NEAR(sites[0].wind.x, exposure * std::sqrt(0.5f), 1e-5f);
  EXPECT_NEAR(sites[0].wind.y, exposure * std::sqrt(0.5f), 1e-5f);
  EXPECT_EQ(sites[1].wind, glm::vec2(0.0f));
  EXPECT_EQ(sites[2].wind, glm::vec2(0.0f));  // a sapling
}

}  // namespace
}  // namespace eco
