#include "sim/conditions/sunlight.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <glm/geometric.hpp>

#include "core/angles.hpp"
#include "sim/conditions/slope.hpp"
#include "terrain_support.hpp"

namespace eco {
namespace {

// Liu and Jordan: a plane tilted beta toward the equator (pole) receives, per day, what
// horizontal ground at latitude phi - beta (phi + beta) receives, but only between the true
// sunrise and sunset at phi. Summed over a year of days.
double annualClosedForm(double latitude_deg, double equivalent_deg) {
  const double phi = radians(latitude_deg), phiE = radians(equivalent_deg);
  double sum = 0.0;
  for (int day = 0; day < 3650; ++day) {
    double n = (day + 0.5) / 10.0;
    double delta = radians(23.44) * std::sin(2.0 * kPi * (284.0 + n) / 365.0);
    double sunset = std::acos(std::clamp(-std::tan(phi) * std::tan(delta), -1.0, 1.0));
    double lit =
        std::min(sunset, std::acos(std::clamp(-std::tan(phiE) * std::tan(delta), -1.0, 1.0)));
    sum += 2.0 * (std::sin(delta) * std::sin(phiE) * lit +
                  std::cos(delta) * std::cos(phiE) * std::sin(lit));
  }
  return sum;
}

struct Result {
  Field sunniness;
  SunlightParts parts;
};

Result sunOn(const Terrain& terrain, double latitude, SunlightSettings settings = {}) {
  Field slope, aspect;
  computeSlopeAspect(terrain, slope, aspect);
  Result r;
  computeSunniness(terrain, slope, aspect, latitude, settings, r.sunniness, &r.parts);
  return r;
}

}  // namespace

TEST(SunPath, DirectionsAreAboveTheHorizonAndWeighted) {
  SunPath sun = makeSunPath(46.0, {});
  ASSERT_EQ(sun.directions.size(), 120u);
  for (std::size_t i = 0; i < sun.directions.size(); ++i) {
    EXPECT_GT(sun.directions[i].z, 0.0);
    EXPECT_NEAR(glm::length(sun.directions[i]), 1.0, 1e-12);
    EXPECT_GT(sun.weights[i], 0.0);
  }
  // Noon of the summer solstice: altitude 90 - 46 + 23.44.
  SunPath june = makeSunPath(46.0, {.days = 365, .hoursPerDay = 1});
  double highest = 0.0;
  for (const auto& d : june.directions) highest = std::max(highest, degrees(std::asin(d.z)));
  EXPECT_NEAR(highest, 90.0 - 46.0 + 23.44, 0.05);
}

TEST(Sunlight, FlatGroundIsTheUnshadedReference) {
  Terrain flat = test::analyticTerrain(24, 24, 10, 10, [](double, double) { return 400.0; });
  Result r = sunOn(flat, 46.0);
  for (std::size_t c = 0; c < r.sunniness.size(); ++c) {
    ASSERT_NEAR(r.parts.directRelative[c], 1.0, 1e-5);
    ASSERT_NEAR(r.parts.skyView[c], 1.0, 1e-5);
    ASSERT_NEAR(r.sunniness[c], 1.0 / r.parts.best, 1e-5);
  }
  EXPECT_GT(r.parts.best, 1.0);  // at 46 N a south slope beats flat ground
}

TEST(Sunlight, SouthAndNorthSlopesMatchTheClosedForm) {
  const double latitude = 46.0, tilt = 30.0, t = std::tan(radians(tilt));
  SunlightSettings fine{.days = 48, .hoursPerDay = 48};
  // Rising northward: faces south. Rising southward: faces north.
  Terrain south =
      test::analyticTerrain(21, 21, 10, 10, [&](double, double n) { return 500.0 + t * n; });
  Terrain north =
      test::analyticTerrain(21, 21, 10, 10, [&](double, double n) { return 800.0 - t * n; });
  const std::size_t centre = south.grid.index(10, 10);
  double southDirect = sunOn(south, latitude, fine).parts.directRelative[centre];
  double northDirect = sunOn(north, latitude, fine).parts.directRelative[centre];
  const double flat = annualClosedForm(latitude, latitude);
  const double expectedSouth = annualClosedForm(latitude, latitude - tilt) / flat;
  const double expectedNorth = annualClosedForm(latitude, latitude + tilt) / flat;
  // Sampling 48 days x 48 sun positions against the closed form's integral: within 1%.
  EXPECT_NEAR(southDirect, expectedSouth, 0.01 * expectedSouth);
  EXPECT_NEAR(northDirect, expectedNorth, 0.01 * expectedNorth);
  EXPECT_NEAR(southDirect / northDirect, expectedSouth / expectedNorth,
              0.02 * expectedSouth / expectedNorth);
  EXPECT_GT(southDirect / northDirect, 2.0);
}

TEST(Sunlight, AWallShadesItsPolewardSide) {
  // An east-west wall 40 m high across flat ground at 46 N; the sun stands in the south.
  Terrain walled = test::analyticTerrain(41, 201, 10, 10, [](double, double n) {
    return std::abs(n - 1000.0) < 15.0 ? 140.0 : 100.0;
  });
  Result r = sunOn(walled, 46.0);
  auto direct = [&](int row) { return r.parts.directRelative[walled.grid.index(20, row)]; };
  // Rows north of the wall (smaller row numbers; the wall is at rows 99-101).
  // At its foot (10 m north) the sun must stand above 76 degrees to reach the ground: never
  // at 46 N. 30 m north it needs 53 degrees, which it reaches around summer noons.
  EXPECT_LT(direct(98), 0.35);
  EXPECT_LT(direct(96), 0.75);
  EXPECT_LT(direct(98), direct(96));
  EXPECT_LT(direct(96), direct(90));
  EXPECT_LT(direct(90), direct(40));
  EXPECT_NEAR(direct(5), 1.0, 0.02);    // 950 m away: unaffected
  EXPECT_NEAR(direct(196), 1.0, 0.02);  // south of the wall, the sun side: unaffected
  EXPECT_GT(direct(104), 0.97);         // right at its sunny foot
}

TEST(Sunlight, IdenticalWhateverTheThreadCount) {
  Terrain hills = test::analyticTerrain(48, 40, 10, 10, [](double e, double n) {
    return 300.0 + 40.0 * std::sin(e / 70.0) * std::cos(n / 50.0);
  });
  Field one, two;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = sunOn(hills, 46.0).sunniness;
  }
  {
    tbb::global_control dual(tbb::global_control::max_allowed_parallelism, 2);
    two = sunOn(hills, 46.0).sunniness;
  }
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t c = 0; c < one.size(); ++c) ASSERT_EQ(one[c], two[c]) << c;
}

TEST(Sunlight, PlaneNormalAndUnshadedRatio) {
  glm::dvec3 n = planeNormal(30.0, 180.0);  // faces south
  EXPECT_NEAR(n.y, -0.5, 1e-12);
  EXPECT_NEAR(n.z, std::cos(radians(30.0)), 1e-12);
  SunPath sun = makeSunPath(46.0, {});
  EXPECT_NEAR(unshadedDirectRatio(sun, {0, 0, 1}), 1.0, 1e-12);
}

}  // namespace eco
