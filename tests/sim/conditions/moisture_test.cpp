#include "sim/conditions/moisture.hpp"

#include <gtest/gtest.h>

#include "sim/conditions/slope.hpp"
#include "terrain_support.hpp"

namespace eco {
namespace {

// A bowl 20 m deep inside a rim at 100 m that slopes down to the map edge.
Terrain bowlTerrain() {
  return test::analyticTerrain(41, 41, 10, 10, [](double e, double n) {
    double r = std::hypot(e - 200.0, n - 200.0);
    return r < 100.0 ? 80.0 + 0.2 * r : 100.0 - 0.05 * (r - 100.0);
  });
}

}  // namespace

TEST(Moisture, FlatPlaneIsUniform) {
  Terrain flat = test::analyticTerrain(30, 30, 10, 10, [](double, double) { return 250.0; });
  Field slope, aspect, moisture;
  computeSlopeAspect(flat, slope, aspect);
  computeMoisture(flat, slope, 1100.0, moisture);
  for (float m : moisture) ASSERT_EQ(m, moisture.front());
  // Level ground in a temperate 1,100 mm climate is fresh: F about 5.
  EXPECT_GT(moisture.front(), 4.0f);
  EXPECT_LT(moisture.front(), 6.0f);
}

TEST(Moisture, TheClimatesNumberMovesOneUnitPer400mm) {
  EXPECT_DOUBLE_EQ(climateMoisture(1100.0), 5.0);
  EXPECT_DOUBLE_EQ(climateMoisture(1500.0), 6.0);
  EXPECT_DOUBLE_EQ(climateMoisture(500.0), 3.5);
}

TEST(Moisture, AHillyLandscapeIsAContinuousFieldMostlyFresh) {
  Terrain hills = generateMidpoint({129, 0.55, 400.0}, 10, 10, 300.0, 7);
  Field slope, aspect, moisture;
  computeSlopeAspect(hills, slope, aspect);
  computeMoisture(hills, slope, 1100.0, moisture);
  std::size_t clamped = 0, fresh = 0;
  for (float m : moisture) {
    clamped += m <= kDriestMoisture || m >= kWettestMoisture;
    fresh += m >= 4.0f && m <= 6.0f;
  }
  const double n = static_cast<double>(moisture.size());
  EXPECT_LT(clamped / n, 0.02);  // no floor or ceiling holding the cells
  EXPECT_GT(fresh / n, 0.6);     // mostly F 4-6, as such a valley's woods are
}

TEST(Moisture, VValleyGathersFlowInItsLine) {
  // Sides fall 0.2 m/m toward the valley line at east = 300 m; the line falls south.
  Terrain valley = test::analyticTerrain(
      61, 61, 10, 10, [](double e, double n) { return 0.2 * std::abs(e - 300.0) + 0.02 * n; });
  Field slope, aspect, moisture;
  computeSlopeAspect(valley, slope, aspect);
  Field accumulation = flowAccumulation(valley, fillDepressions(valley), slope);
  computeMoisture(valley, slope, 1100.0, moisture);
  for (int y = 10; y < 50; ++y) {
    std::size_t line = valley.grid.index(30, y);
    for (int x : {5, 15, 25, 35, 45, 55}) {
      ASSERT_GT(accumulation[line], accumulation[valley.grid.index(x, y)]) << x << "," << y;
      ASSERT_GT(moisture[line], moisture[valley.grid.index(x, y)]) << x << "," << y;
    }
  }
  // Downstream along the line, more has gathered.
  EXPECT_GT(accumulation[valley.grid.index(30, 55)], accumulation[valley.grid.index(30, 10)]);
  // Everything upstream of the line's lowest cell drains through it: about half the map.
  EXPECT_GT(accumulation[valley.grid.index(30, 59)], 0.4f * valley.grid.cellCount());
}

TEST(Moisture, PitsFillToTheirSpillLevel) {
  Terrain bowl = bowlTerrain();
  std::vector<double> filled = fillDepressions(bowl);
  const std::size_t centre = bowl.grid.index(20, 20);
  EXPECT_GT(filled[centre], 99.0);  // the pond reaches the rim
  EXPECT_LT(filled[centre], 100.01);
  for (std::size_t c = 0; c < filled.size(); ++c) ASSERT_GE(filled[c], bowl.height_m[c]);
  // As a pond, the bowl is wet (F 9 or more) all over, its outside is not.
  bowl.closedDepressions = ClosedDepressions::Pond;
  Field slope(bowl.grid.cellCount(), 5.0f), moisture;
  computeMoisture(bowl, slope, 1100.0, moisture);
  EXPECT_GE(moisture[centre], kPondMoisture);
  EXPECT_GE(moisture[bowl.grid.index(25, 20)], kPondMoisture);
  EXPECT_LT(moisture[bowl.grid.index(20, 2)], kPondMoisture);  // outside the rim
}

TEST(Moisture, DrainedPitsAreAsMoistAsTheirWetnessIndexSays) {
  // The bowl, drained (the default): no cell is held at the pond's F 9;
  // every cell, in the bowl or outside it, has the climate's number plus a quarter unit per
  // unit of TWI, its catchment routed over the filled surface.
  Terrain bowl = bowlTerrain();
  ASSERT_EQ(bowl.closedDepressions, ClosedDepressions::Drain);
  Field slope, aspect, moisture;
  computeSlopeAspect(bowl, slope, aspect);
  computeMoisture(bowl, slope, 1100.0, moisture);
  const Field twi = wetnessIndex(bowl, flowAccumulation(bowl, fillDepressions(bowl), slope), slope);
  for (std::size_t c = 0; c < moisture.size(); ++c)
    ASSERT_NEAR(moisture[c], 5.0 + kMoisturePerWetness * (twi[c] - kReferenceWetness), 1e-4) << c;
  // The bowl's sloping side (11 degrees) is fresh, not wet.
  const std::size_t side = bowl.grid.index(25, 20);
  EXPECT_GT(moisture[side], 4.0f);
  EXPECT_LT(moisture[side], 7.0f);
}

TEST(Moisture, WetterClimateIsWetter) {
  Terrain slope30 = test::analyticTerrain(20, 20, 10, 10, [](double e, double) { return 0.3 * e; });
  Field slope, aspect, dry, wet;
  computeSlopeAspect(slope30, slope, aspect);
  computeMoisture(slope30, slope, 400.0, dry);
  computeMoisture(slope30, slope, 2000.0, wet);
  for (std::size_t c = 0; c < dry.size(); ++c) ASSERT_LT(dry[c], wet[c]);
}

TEST(Moisture, MoistureOfTheTerrainAloneIsTheConditionsField) {
  const Terrain bowl = bowlTerrain();
  Field slope, aspect, moisture;
  computeSlopeAspect(bowl, slope, aspect);
  computeMoisture(bowl, slope, 900.0, moisture);
  EXPECT_EQ(moistureOf(bowl, 900.0), moisture);
}

}  // namespace eco
