#include "sim/conditions/slope.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/angles.hpp"
#include "terrain_support.hpp"

namespace eco {

TEST(Slope, FlatPlaneIsLevel) {
  Terrain flat = test::analyticTerrain(20, 20, 10, 10, [](double, double) { return 300.0; });
  Field slope, aspect;
  computeSlopeAspect(flat, slope, aspect);
  for (std::size_t c = 0; c < slope.size(); ++c) {
    EXPECT_EQ(slope[c], 0.0f);
    EXPECT_EQ(aspect[c], -1.0f);
  }
}

TEST(Slope, TiltedPlaneOfKnownSlopeAndAspect) {
  const double tan20 = std::tan(radians(20.0));
  // Rising toward the east: it faces (falls toward) the west.
  Terrain west =
      test::analyticTerrain(30, 30, 10, 10, [&](double e, double) { return 100.0 + tan20 * e; });
  Field slope, aspect;
  computeSlopeAspect(west, slope, aspect);
  for (std::size_t c = 0; c < slope.size(); ++c) {
    ASSERT_NEAR(slope[c], 20.0, 0.1);
    ASSERT_NEAR(aspect[c], 270.0, 0.1);
  }
}

TEST(Slope, NonSquareCells) {
  // Rising 0.5 m per metre toward the north on 10 m x 30 m cells: 26.565 degrees, facing south.
  Terrain south = test::analyticTerrain(12, 12, 10, 30, [](double, double n) { return 0.5 * n; });
  Field slope, aspect;
  computeSlopeAspect(south, slope, aspect);
  const std::size_t inner = south.grid.index(6, 6);
  EXPECT_NEAR(slope[inner], degrees(std::atan(0.5)), 0.01);
  EXPECT_NEAR(aspect[inner], 180.0, 0.01);
  // The same plane on the other axis: a different cell size must not change the slope.
  Terrain east = test::analyticTerrain(12, 12, 30, 10, [](double e, double) { return 0.5 * e; });
  computeSlopeAspect(east, slope, aspect);
  EXPECT_NEAR(slope[east.grid.index(6, 6)], degrees(std::atan(0.5)), 0.01);
}

}  // namespace eco
