#include "render/scene/sun.hpp"
#include "core/angles.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

namespace eco {
namespace {

TEST(Sun, StandsInTheSouthAtNoonAtTheComplementOfTheLatitudeAtTheEquinox) {
  // Day 81 is close to the March equinox (declination ~0 by Cooper's formula).
  const glm::vec3 s = sunWorldDirection(46.0, {81.0, 12.0});
  EXPECT_NEAR(degrees(std::asin(s.y)), 44.0, 0.5);
  EXPECT_NEAR(s.x, 0.0f, 1e-4f);
  EXPECT_GT(s.z, 0.0f);  // z is south
}

TEST(Sun, RisesInTheEastAndSetsInTheWest) {
  EXPECT_GT(sunWorldDirection(46.0, {172.0, 8.0}).x, 0.5f);
  EXPECT_LT(sunWorldDirection(46.0, {172.0, 16.0}).x, -0.5f);
  EXPECT_LT(sunWorldDirection(46.0, {172.0, 0.0}).y, 0.0f);  // midnight
  // Midsummer noon at 46 N: 90 - 46 + 23.44.
  EXPECT_NEAR(degrees(std::asin(sunWorldDirection(46.0, {172.0, 12.0}).y)), 67.4, 0.3);
}

TEST(Sun, LightDimsAndReddensTowardTheHorizonAndGoesAtNight) {
  const Lighting noon = lightingFor(46.0, {172.0, 12.0});
  const Lighting evening = lightingFor(46.0, {172.0, 19.5});
  const Lighting night = lightingFor(46.0, {172.0, 0.0});
  EXPECT_GT(noon.sunColor.b, evening.sunColor.b);
  EXPECT_GT(evening.sunColor.r / evening.sunColor.b, noon.sunColor.r / noon.sunColor.b);
  EXPECT_EQ(night.sunColor, glm::vec3(0.0f));
  EXPECT_LT(night.ambient.g, noon.ambient.g);
}

}  // namespace
}  // namespace eco
