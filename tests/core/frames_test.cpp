#include "core/frames.hpp"

#include <gtest/gtest.h>

namespace eco {
namespace {

TEST(Frames, MapAndWorldAreOneRotationApart) {
  const glm::vec3 world = worldFromMap(120.5, 340.25, 512.0);
  EXPECT_EQ(world, glm::vec3(120.5f, 512.0f, -340.25f));  // x east, y up, z south
  EXPECT_EQ(mapFromWorld(world), glm::dvec3(120.5, 340.25, 512.0));
  EXPECT_EQ(worldFromMap(glm::vec3(1.0f, 2.0f, 3.0f)), glm::vec3(1.0f, 3.0f, -2.0f));
  // East, north and up as directions.
  EXPECT_EQ(worldDirectionFromMap({1, 0, 0}), glm::vec3(1, 0, 0));
  EXPECT_EQ(worldDirectionFromMap({0, 1, 0}), glm::vec3(0, 0, -1));
  EXPECT_EQ(worldDirectionFromMap({0, 0, 1}), glm::vec3(0, 1, 0));
}

TEST(Frames, BearingsTurnClockwiseFromNorth) {
  const glm::dvec2 north = mapDirectionOfBearing(0.0), east = mapDirectionOfBearing(90.0);
  EXPECT_NEAR(north.x, 0.0, 1e-12);
  EXPECT_NEAR(north.y, 1.0, 1e-12);
  EXPECT_NEAR(east.x, 1.0, 1e-12);
  EXPECT_NEAR(east.y, 0.0, 1e-12);
  const glm::dvec3 south = worldDirectionOfBearing(180.0);
  EXPECT_NEAR(south.z, 1.0, 1e-12);  // world z is south
  EXPECT_NEAR(bearingOfWorldDirection(glm::vec3(worldDirectionOfBearing(135.0))), 135.0f, 1e-4f);
  EXPECT_NEAR(bearingOfWorldDirection({-1.0f, 0.3f, 0.0f}), -90.0f, 1e-4f);  // west
}

TEST(Frames, AWindBlowsAwayFromWhereItComesFrom) {
  const glm::dvec3 fromWest = worldDownwindOf(270.0);  // blows toward the east, +x
  EXPECT_NEAR(fromWest.x, 1.0, 1e-12);
  EXPECT_NEAR(fromWest.z, 0.0, 1e-12);
  const glm::dvec3 fromSouth = worldDownwindOf(180.0);  // blows north, -z
  EXPECT_NEAR(fromSouth.z, -1.0, 1e-12);
  const glm::dvec2 mapFromSouth = mapDownwindOf(180.0);
  EXPECT_NEAR(mapFromSouth.y, 1.0, 1e-12);
}

}  // namespace
}  // namespace eco
