#include "render/scene/camera.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "render/scene/culling.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

TEST(Camera, YawIsACompassBearingAndPitchLooksUp) {
  Camera c;
  c.yaw_deg = 0.0f;
  EXPECT_NEAR(glm::distance(c.forward(), glm::vec3(0, 0, -1)), 0.0f, 1e-6f);  // north
  c.yaw_deg = 90.0f;
  EXPECT_NEAR(glm::distance(c.forward(), glm::vec3(1, 0, 0)), 0.0f, 1e-6f);  // east
  EXPECT_NEAR(glm::distance(c.right(), glm::vec3(0, 0, 1)), 0.0f, 1e-6f);    // then south
  c.pitch_deg = 90.0f;
  EXPECT_NEAR(c.forward().y, 1.0f, 1e-6f);
}

TEST(Camera, ParsesFiveNumbersAndRejectsTheRest) {
  auto c = parseCamera("100,200,350.5,45,-10");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->position, worldFromMap(100, 200, 350.5));
  EXPECT_FLOAT_EQ(c->yaw_deg, 45.0f);
  EXPECT_FLOAT_EQ(c->pitch_deg, -10.0f);
  EXPECT_FALSE(parseCamera("1,2,3,4"));
  EXPECT_FALSE(parseCamera("1,2,3,4,5,6"));
  EXPECT_FALSE(parseCamera("1,2,x,4,5"));
  EXPECT_FALSE(parseCamera("1,2,3,4,95"));
  EXPECT_FALSE(parseCamera("1,,3,4,5"));
}

TEST(Camera, TheOverviewSeesTheWholeMapAndTheGroundViewStandsOnIt) {
  Terrain terrain = test::flatTerrain(65, 10.0);
  const Camera overview = presetCamera(CameraPreset::Overview, terrain);
  const Frustum f = Frustum::fromMatrix(overview.projection(16.0f / 9.0f) * overview.view());
  for (double east : {0.0, 640.0})
    for (double north : {0.0, 640.0})
      EXPECT_TRUE(f.intersectsSphere(worldFromMap(east, north, 100.0), 0.0f))
          << east << "," << north;
  const Camera ground = presetCamera(CameraPreset::Ground, terrain);
  EXPECT_NEAR(ground.position.y, 101.7f, 1e-4f);
}

}  // namespace
}  // namespace eco
