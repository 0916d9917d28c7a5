#include "sim/ecology/suitability.hpp"

#include <gtest/gtest.h>

#include "terrain_support.hpp"

namespace eco {
namespace {

ConditionFields oneCell(float altitude, float slope, float moisture, float wind, float sun) {
  ConditionFields f;
  f.grid = Grid{1, 1, 10.0, 10.0};
  f.altitude_m = {altitude}, f.slope_deg = {slope}, f.aspect_deg = {-1.0f};
  f.moisture = {moisture}, f.windiness = {wind}, f.sunniness = {sun};
  return f;
}

ToleranceCurves ramps() {
  ToleranceCurves t;
  t.altitude_m = Polyline({{0, 1}, {1000, 0}});
  t.slope_deg = Polyline({{0, 1}, {50, 0}});
  t.moisture = Polyline::constant(1.0);
  t.windiness = Polyline({{0, 1}, {1, 0}});
  return t;
}

TEST(Suitability, EachConditionThroughItsCurve) {
  auto s = conditionSuitabilities(ramps(), oneCell(250, 10, 0.5, 0.5, 0.5), 0);
  EXPECT_DOUBLE_EQ(s[0], 0.75);
  EXPECT_DOUBLE_EQ(s[1], 0.8);
  EXPECT_DOUBLE_EQ(s[2], 1.0);
  EXPECT_DOUBLE_EQ(s[3], 0.5);
  EXPECT_EQ(s.size(), static_cast<std::size_t>(kConditionCount));  // light acts elsewhere
}

TEST(Suitability, MinimumIsLiebigsLawAndProductTheOption) {
  const ConditionFields f = oneCell(250, 10, 0.5, 0.5, 0.5);
  EXPECT_DOUBLE_EQ(siteSuitability(ramps(), f, SuitabilityRule::Minimum)[0], 0.5f);
  EXPECT_NEAR(siteSuitability(ramps(), f, SuitabilityRule::Product)[0], 0.75 * 0.8 * 1.0 * 0.5,
              1e-6);
  // One unbearable condition stops the species whatever the others.
  EXPECT_EQ(siteSuitability(ramps(), oneCell(1200, 0, 0.5, 0, 1), SuitabilityRule::Minimum)[0],
            0.0f);
}

}  // namespace
}  // namespace eco
