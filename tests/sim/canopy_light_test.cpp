#include "sim/canopy_light.hpp"

#include <cmath>
#include <numeric>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "terrain_support.hpp"

namespace eco {
namespace {

Terrain flat() {
  return test::analyticTerrain(41, 41, 5.0, 5.0, [](double, double) { return 100.0; });
}

LightDirections straightUp() {
  return {{glm::dvec3(0.0, 0.0, 1.0)}, {1.0}};
}

Crown crownAt(float east, float north, float transmittance) {
  Crown c;
  c.centre = {east, north, 110.0f};
  c.radius_m = 3.0f;
  c.halfLength_m = 4.0f;
  c.opticalDepthPerMetre = -std::log(transmittance) / 8.0f;
  c.owner = 0;
  return c;
}

TEST(CanopyLight, DirectionWeightsSumToOne) {
  const LightDirections sky = makeLightDirections(46.0, 16);
  ASSERT_EQ(sky.direction.size(), 16u);
  EXPECT_NEAR(std::accumulate(sky.weight.begin(), sky.weight.end(), 0.0), 1.0, 1e-9);
  for (const glm::dvec3& d : sky.direction) EXPECT_GT(d.z, 0.0);
}

TEST(CanopyLight, OpenGroundGetsAllTheLight) {
  const Terrain terrain = flat();
  CanopyScene scene(terrain);
  EXPECT_NEAR(scene.lightAt({100.0f, 100.0f, 100.5f}, -1, makeLightDirections(46.0, 16)), 1.0,
              1e-12);
}

TEST(CanopyLight, AVerticalRayThroughACrownKeepsItsTransmittance) {
  const Terrain terrain = flat();
  CanopyScene scene(terrain);
  scene.setCrowns({crownAt(100.0f, 100.0f, 0.2f)});
  // Through the centre: the whole crown length, so exactly T. Off-centre, a shorter chord.
  EXPECT_NEAR(scene.lightAt({100.0f, 100.0f, 100.5f}, -1, straightUp()), 0.2, 1e-5);
  const double chord = 8.0 * std::sqrt(1.0 - 1.5 * 1.5 / 9.0);
  EXPECT_NEAR(scene.lightAt({101.5f, 100.0f, 100.5f}, -1, straightUp()), std::pow(0.2, chord / 8.0),
              1e-5);
  EXPECT_NEAR(scene.lightAt({104.0f, 100.0f, 100.5f}, -1, straightUp()), 1.0, 1e-12);
  // Two crowns one above the other multiply, and a plant's own crown is ignored.
  Crown upper = crownAt(100.0f, 100.0f, 0.5f);
  upper.centre.z = 120.0f;
  upper.owner = 1;
  scene.setCrowns({crownAt(100.0f, 100.0f, 0.2f), upper});
  EXPECT_NEAR(scene.lightAt({100.0f, 100.0f, 100.5f}, -1, straightUp()), 0.1, 1e-5);
  EXPECT_NEAR(scene.lightAt({100.0f, 100.0f, 100.5f}, 0, straightUp()), 0.5, 1e-5);
}

TEST(CanopyLight, TerrainBlocksLight) {
  // A wall 50 m high east of x = 100 m; a point west of it loses the eastern sky.
  const Terrain terrain = test::analyticTerrain(
      41, 41, 5.0, 5.0, [](double east, double) { return east > 100.0 ? 150.0 : 100.0; });
  CanopyScene scene(terrain);
  const LightDirections east = {{glm::normalize(glm::dvec3(1.0, 0.0, 0.3))}, {1.0}};
  const LightDirections west = {{glm::normalize(glm::dvec3(-1.0, 0.0, 0.3))}, {1.0}};
  EXPECT_EQ(scene.lightAt({80.0f, 100.0f, 100.5f}, -1, east), 0.0);
  EXPECT_EQ(scene.lightAt({80.0f, 100.0f, 100.5f}, -1, west), 1.0);
}

}  // namespace
}  // namespace eco
