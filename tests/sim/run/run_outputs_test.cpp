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
  const std::vector<StatsRow> rows = statsOfYear(ecosystem);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].alive, 1);
  EXPECT_NEAR(rows[0].meanHeight_m, p.height_m[0], 1e-6);
  EXPECT_NEAR(rows[0].basalArea_m2PerHa, std::numbers::pi / 4.0 * p.dbh_m[0] * p.dbh_m[0], 1e-6);
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

}  // namespace
}  // namespace eco
