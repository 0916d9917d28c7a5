#include "sim/ecology/canopy_light.hpp"

#include <cmath>
#include <numeric>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/random.hpp"
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

TEST(CanopyLight, TracingManyProbesGivesEachProbesOwnLight) {
  const Terrain terrain = flat();
  CanopyScene scene(terrain);
  std::vector<Crown> crowns;
  Rng rng(streamKey(9, purpose("test")));
  for (int i = 0; i < 300; ++i) {
    Crown c = crownAt(static_cast<float>(20.0 + 160.0 * rng.uniform()),
                      static_cast<float>(20.0 + 160.0 * rng.uniform()), 0.2f);
    c.centre.z = static_cast<float>(104.0 + 10.0 * rng.uniform());
    c.owner = i;
    crowns.push_back(c);
  }
  scene.setCrowns(crowns);
  std::vector<LightProbe> probes;
  for (int i = 0; i < 300; i += 3)  // each crown top, its own crown left out
    probes.push_back({crowns[i].centre + glm::vec3(0.0f, 0.0f, crowns[i].halfLength_m), i});
  for (int i = 0; i < 37; ++i)  // points on the ground
    probes.push_back({{10.0f + 5.0f * i, 100.0f, 100.5f}, -1});
  const LightDirections sky = makeLightDirections(46.0, 16);
  const std::vector<float> light = scene.lightAt(probes, sky);
  ASSERT_EQ(light.size(), probes.size());
  double spread = 0.0;
  for (std::size_t k = 0; k < probes.size(); ++k) {
    EXPECT_EQ(light[k], static_cast<float>(scene.lightAt(probes[k].point, probes[k].self, sky)));
    spread += std::abs(light[k] - light[0]);
  }
  EXPECT_GT(spread, 1.0);  // the probes do see different canopies
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
