#include "sim/run/run_outputs.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "ecosystem_support.hpp"
#include "terrain_support.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

using test::OneHectare;

TEST_F(OneHectare, BasalAreaCoverAndCanopyFromThePlants) {
  ecosystem.plant(0, 41.0, 43.0, 100);
  const Plants& p = ecosystem.plants();
  const std::vector<StatsRow> rows = statsOfYear(ecosystem, PlanYear(ecosystem.species().size()));
  ASSERT_EQ(rows.size(), 2u);  // the species, and the whole stand
  EXPECT_EQ(rows[1].species, kAllSpecies);
  for (const StatsRow& row : rows) {
    EXPECT_EQ(row.alive, 1);
    EXPECT_NEAR(row.meanHeight_m, p.height_m[0], 1e-6);
    EXPECT_NEAR(row.basalArea_m2PerHa, std::numbers::pi / 4.0 * p.dbh_m[0] * p.dbh_m[0], 1e-6);
    ASSERT_GE(p.dbh_m[0], 0.1f);
    EXPECT_DOUBLE_EQ(row.stemsPerHa, 1.0);
    EXPECT_NEAR(row.qmd_cm, 100.0 * p.dbh_m[0], 1e-4);
    EXPECT_NEAR(row.dominantHeight_m, p.height_m[0], 1e-6);
  }
  // The hectare is the map: its one tree makes the densest block.
  EXPECT_NEAR(rows[1].densestHectareBasalArea_m2PerHa, rows[1].basalArea_m2PerHa, 1e-9);
  // The cell centres inside the crown circle, counted directly.
  int inside = 0;
  const Grid& g = terrain.grid;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x)
      inside += std::hypot(g.eastOf(x) - 41.0, g.northOf(y) - 43.0) <= p.crownRadius_m[0];
  ASSERT_GT(inside, 0);
  EXPECT_NEAR(rows[0].coverFraction, inside / 100.0, 1e-12);
  const Field canopy = canopyHeight(ecosystem);
  int covered = 0;
  for (float h : canopy) {
    if (h > 0.0f) {
      EXPECT_EQ(h, p.height_m[0]);
    }
    covered += h > 0.0f;
  }
  EXPECT_EQ(covered, inside);
}

TEST_F(OneHectare, TheStandCoversEveryCellSomeSpeciesCovers) {
  // Two species whose trees' crowns overlap, and a third tree apart: each species' cover
  // counts its own crowns, the stand's counts the shared cells once.
  Ecosystem mixed(terrain, fields,
                  {test::inEcosystem(test::testSpecies("a", {}), fields),
                   test::inEcosystem(test::testSpecies("b", {}), fields)},
                  EcosystemSettings{});
  mixed.plant(0, 30.0, 50.0, 100);
  mixed.plant(1, 33.0, 50.0, 100);
  mixed.plant(1, 80.0, 20.0, 100);
  const Plants& p = mixed.plants();
  const Grid& g = terrain.grid;
  std::vector<int> cells(3, 0);  // species a, species b, the stand
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      bool under[2] = {false, false};
      for (std::size_t i = 0; i < p.size(); ++i)
        under[p.species[i]] = under[p.species[i]] ||
                              std::hypot(g.eastOf(x) - p.east_m[i], g.northOf(y) - p.north_m[i]) <=
                                  p.crownRadius_m[i];
      cells[0] += under[0];
      cells[1] += under[1];
      cells[2] += under[0] || under[1];
    }
  ASSERT_LT(cells[2], cells[0] + cells[1]);  // the crowns do overlap
  const std::vector<StatsRow> rows = statsOfYear(mixed, PlanYear(mixed.species().size()));
  ASSERT_EQ(rows.size(), 3u);
  for (std::size_t r = 0; r < rows.size(); ++r)
    EXPECT_NEAR(rows[r].coverFraction, cells[r] / 100.0, 1e-12) << "row " << r;
  EXPECT_EQ(rows[2].alive, 3);
}

}  // namespace
}  // namespace eco
