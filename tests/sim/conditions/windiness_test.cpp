#include "sim/conditions/windiness.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "terrain_support.hpp"

namespace eco {

TEST(Windiness, FlatPlaneIsUniform) {
  Terrain flat = test::analyticTerrain(40, 40, 10, 10, [](double, double) { return 500.0; });
  Field wind;
  computeWindiness(flat, 270.0, wind);
  // Open level ground has the same windiness whatever its size or altitude.
  for (float w : wind) ASSERT_FLOAT_EQ(w, static_cast<float>(kOpenGroundWindiness));
}

TEST(Windiness, TopographicPositionIsTheRiseAboveTheMeanAround) {
  // On a tilted plane a cell is as high as the mean of a square centred on it; a 50 m hill
  // on a plain rises atan(50 m / radius) less its share of the square's mean.
  Terrain plane = test::analyticTerrain(41, 41, 10, 10, [](double e, double) { return 0.2 * e; });
  const Field tilted = elevationAngle(plane, 100.0);
  EXPECT_NEAR(tilted[plane.grid.index(20, 20)], 0.0f, 1e-4f);
  Terrain hill = test::analyticTerrain(
      41, 41, 10, 10, [](double e, double n) { return e == 200.0 && n == 200.0 ? 50.0 : 0.0; });
  const Field rise = elevationAngle(hill, 100.0);  // a 21 x 21 square of 441 cells
  EXPECT_NEAR(rise[hill.grid.index(20, 20)],
              std::atan((50.0 - 50.0 / 441.0) / 100.0) * 180.0 / M_PI, 1e-3);
  EXPECT_LT(rise[hill.grid.index(25, 20)], 0.0f);  // around it, below the mean
}

TEST(Windiness, IsOnAnAbsoluteScaleNotTheMapsOwnRange) {
  // The same hills, and the same hills with a hundredth of the relief: a near-plain must
  // not stretch its few centimetres over the whole scale.
  const Terrain hills = generateMidpoint({65, 0.55, 300.0}, 10, 10, 300.0, 4);
  Terrain plain = hills;
  for (float& h : plain.height_m) h = 300.0f + 0.01f * (h - 300.0f);
  Field windHills, windPlain;
  computeWindiness(hills, 270.0, windHills);
  computeWindiness(plain, 270.0, windPlain);
  auto range = [](const Field& f) {
    const auto [lo, hi] = std::minmax_element(f.begin(), f.end());
    return *hi - *lo;
  };
  ASSERT_GT(range(windHills), 0.2f);
  EXPECT_LT(range(windPlain), 0.1f * range(windHills));
  for (float w : windPlain) EXPECT_NEAR(w, kOpenGroundWindiness, 0.05);
}

TEST(Windiness, LeeOfARidgeIsCalmer) {
  // A north-south ridge at east = 400 m across a west wind.
  Terrain ridge = test::analyticTerrain(81, 41, 10, 10, [](double e, double) {
    return 200.0 + std::max(0.0, 100.0 - 0.5 * std::abs(e - 400.0));
  });
  Field sx = upwindSlope(ridge, 270.0);
  Field wind;
  computeWindiness(ridge, 270.0, wind);
  // Cells at the same height on either side: windward (west, x = 30) and lee (east, x = 50).
  std::size_t windward = ridge.grid.index(30, 20), lee = ridge.grid.index(50, 20);
  ASSERT_FLOAT_EQ(ridge.height_m[windward], ridge.height_m[lee]);
  EXPECT_LT(sx[windward], 0.0f);  // open, falling ground upwind
  EXPECT_GT(sx[lee], 10.0f);      // the ridge stands upwind
  EXPECT_LT(wind[lee], wind[windward]);
  // From the east, the sides swap.
  computeWindiness(ridge, 90.0, wind);
  EXPECT_GT(wind[lee], wind[windward]);
}

TEST(Windiness, HigherIsWindierOnOpenGround) {
  Terrain cone = test::analyticTerrain(41, 41, 10, 10, [](double e, double n) {
    return 300.0 - 0.1 * std::hypot(e - 200, n - 200);
  });
  Field wind;
  computeWindiness(cone, 0.0, wind);
  EXPECT_GT(wind[cone.grid.index(20, 20)], wind[cone.grid.index(20, 38)]);
}

}  // namespace eco
