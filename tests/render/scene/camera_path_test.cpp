#include "render/scene/camera_path.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

Terrain hills() {
  return generateMidpoint({33, 0.5, 60.0}, 10.0, 10.0, 300.0, 9);
}

TEST(CameraPath, LookingAtFacesTheTarget) {
  const Camera c = lookingAt({0, 10, 0}, {30, 0, -40});
  EXPECT_LT(glm::distance(c.forward(), glm::normalize(glm::vec3(30, -10, -40))), 1e-5f);
}

TEST(CameraPath, TheOrbitGoesOnceAroundTheCentreLookingAtIt) {
  const Terrain terrain = hills();
  const CameraPath orbit = orbitPath(terrain);
  const glm::vec3 centre = worldFromMap(160, 160, terrain.altitudeAt(160, 160));
  EXPECT_LT(glm::distance(orbit(0.0).position, orbit(1.0).position), 1e-3f);
  EXPECT_GT(orbit(0.0).position.z, centre.z);  // starts in the south
  const float radius = glm::distance(orbit(0.0).position, centre);
  for (double u = 0.0; u <= 1.0; u += 0.1) {
    const Camera c = orbit(u);
    EXPECT_NEAR(glm::distance(c.position, centre), radius, 1e-2f);
    EXPECT_LT(glm::distance(c.forward(), glm::normalize(centre - c.position)), 1e-4f);
  }
}

TEST(CameraPath, TheFlyoverMovesNorthAboveTheGround) {
  const Terrain terrain = hills();
  const CameraPath flyover = flyoverPath(terrain);
  float previousNorth = -1.0f;
  for (double u = 0.0; u <= 1.0; u += 0.05) {
    const Camera c = flyover(u);
    EXPECT_GT(-c.position.z, previousNorth);
    previousNorth = -c.position.z;
    EXPECT_GE(c.position.y, groundBelow(terrain, c.position) + 80.0f - 1e-3f);
  }
}

TEST(CameraPath, KeyframesAreHitAtTheirTimesAndTheGroundIsNeverEntered) {
  const Terrain terrain = hills();
  std::vector<CameraKey> keys{{0.0, worldFromMap(20, 20, 500), worldFromMap(160, 160, 300)},
                              {2.0, worldFromMap(160, 40, 450), worldFromMap(160, 200, 300)},
                              {3.0, worldFromMap(300, 100, 0), worldFromMap(160, 160, 300)}};
  const CameraPath path = keyframePath(keys, terrain);
  EXPECT_LT(glm::distance(path(0.0).position, keys[0].position), 1e-3f);
  EXPECT_LT(glm::distance(path(2.0 / 3.0).position, keys[1].position), 1e-3f);
  // The last key lies underground: the camera stays 2 m above it.
  const Camera last = path(1.0);
  EXPECT_NEAR(last.position.y, terrain.altitudeAt(300, 100) + kCameraClearance_m, 1e-3f);
  for (double u = 0.0; u <= 1.0; u += 0.01) {
    const Camera c = path(u);
    EXPECT_GE(c.position.y, groundBelow(terrain, c.position) + 2.0f - 1e-3f);
  }
}

TEST(CameraPath, AKeyframeFileIsReadAndItsErrorsNameTheLine) {
  const Terrain terrain = hills();
  const auto dir = test::freshDirectory("camera_path");
  test::writeFile(dir / "good.toml",
                  "[[key]]\ntime = 0\nposition = [10, 10, 600]\nlook_at = [160, 160, 300]\n"
                  "[[key]]\ntime = 5\nposition = [300, 300, 600]\nlook_at = [160, 160, 300]\n");
  const CameraPath path = loadCameraPath(dir / "good.toml", terrain);
  EXPECT_LT(glm::distance(path(1.0).position, worldFromMap(300, 300, 600)), 1e-3f);
  test::writeFile(dir / "back.toml",
                  "[[key]]\ntime = 3\nposition = [10, 10, 600]\nlook_at = [160, 160, 300]\n"
                  "[[key]]\ntime = 1\nposition = [300, 300, 600]\nlook_at = [160, 160, 300]\n");
  try {
    loadCameraPath(dir / "back.toml", terrain);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 6) << e.what();
    EXPECT_NE(std::string(e.what()).find("increase"), std::string::npos);
  }
  test::writeFile(dir / "one.toml",
                  "[[key]]\ntime = 0\nposition = [1, 1, 600]\nlook_at = [2, 2, 0]\n");
  EXPECT_THROW(loadCameraPath(dir / "one.toml", terrain), InputError);
  test::writeFile(dir / "typo.toml",
                  "[[key]]\ntime = 0\nposition = [10, 10, 600]\nlookat = [160, 160, 300]\n"
                  "[[key]]\ntime = 5\nposition = [300, 300, 600]\nlook_at = [160, 160, 300]\n");
  EXPECT_THROW(loadCameraPath(dir / "typo.toml", terrain), InputError);
}

}  // namespace
}  // namespace eco
