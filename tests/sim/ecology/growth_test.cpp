#include "sim/ecology/growth.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace eco {
namespace {

LifeHistory life() {
  LifeHistory h;
  h.maxAge_years = 200;
  h.height_m = {30.0, 0.03, 1.4};
  h.dbh_m = {1.0, 0.012, 1.3};
  h.crownRadius_m = Polyline({{0.0, 0.3}, {1.0, 9.3}});
  h.seedsPerYear = 40.0;
  h.stressYearsTolerated = 4;
  return h;
}

TEST(Growth, FullVigorFollowsTheChapmanRichardsCurve) {
  const GrowthCurve curve = life().height_m;
  double h = curve.at(1.0);
  for (int age = 1; age < 120; ++age) h = grownValue(curve, h, 1.0);
  EXPECT_NEAR(h, curve.at(120.0), 1e-9);
  EXPECT_NEAR(curve.ageOf(curve.at(37.0)), 37.0, 1e-9);
}

TEST(Growth, VigorScalesTheIncrementAndNothingPassesTheMaximum) {
  const GrowthCurve curve = life().height_m;
  const double h = curve.at(20.0);
  const double full = grownValue(curve, h, 1.0) - h;
  EXPECT_NEAR(grownValue(curve, h, 0.25) - h, 0.25 * full, 1e-12);
  EXPECT_EQ(grownValue(curve, h, 0.0), h);
  EXPECT_EQ(grownValue(curve, 30.0, 1.0), 30.0);
  EXPECT_LE(grownValue(curve, 29.9999, 1.0), 30.0);
}

TEST(Growth, CrownFollowsTheAllometryButIsNoWiderThanHalfTheHeight) {
  EXPECT_NEAR(crownRadiusOf(life(), 0.5, 30.0), 4.8, 1e-12);
  EXPECT_NEAR(crownRadiusOf(life(), 0.0, 0.2), 0.1, 1e-12);
}

TEST(Growth, MortalityIsJabowasIntrinsicRateStressAndTheMaximumAge) {
  const LifeHistory h = life();
  EXPECT_NEAR(mortalityProbability(h, 50, 0), 4.605 / 200.0, 1e-12);
  // 1 % of a cohort lives to the maximum age.
  EXPECT_NEAR(std::pow(1.0 - mortalityProbability(h, 50, 0), 200), 0.01, 0.001);
  EXPECT_NEAR(mortalityProbability(h, 50, 3), 4.605 / 200.0, 1e-12);
  EXPECT_NEAR(mortalityProbability(h, 50, 4), 0.368, 1e-12);
  EXPECT_EQ(mortalityProbability(h, 200, 0), 1.0);
}

TEST(Growth, SeedsScaleWithTheSquareOfTheStemDiameter) {
  EXPECT_NEAR(seedCount(life(), 0.3, 1.0), 40.0, 1e-12);
  EXPECT_NEAR(seedCount(life(), 0.6, 1.0), 160.0, 1e-12);
  EXPECT_NEAR(seedCount(life(), 0.3, 0.5), 20.0, 1e-12);
  LifeHistory shrub = life();
  shrub.dbh_m.max = 0.15;
  EXPECT_NEAR(seedCount(shrub, 0.15, 1.0), 40.0, 1e-12);
}

}  // namespace
}  // namespace eco
