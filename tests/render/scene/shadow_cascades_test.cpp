#include "render/scene/shadow_cascades.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "render/scene/sun.hpp"

namespace eco {
namespace {

constexpr int kMapSize = 2048;

// Where a world point falls in a cascade's map: [0, 1] across, depth in [0, 1].
glm::vec3 mapCoordinates(const ShadowBox& box, glm::vec3 world) {
  const glm::vec4 p = box.lightViewProj * glm::vec4(world, 1.0f);
  return glm::vec3(p) / p.w * 0.5f + 0.5f;
}

bool inMap(const ShadowBox& box, glm::vec3 world) {
  const glm::vec3 q = mapCoordinates(box, world);
  return q.x >= 0.0f && q.x <= 1.0f && q.y >= 0.0f && q.y <= 1.0f && q.z >= 0.0f && q.z <= 1.0f;
}

Camera cameraLookingNorth() {
  Camera camera;
  camera.position = {500.0f, 320.0f, 800.0f};
  camera.pitch_deg = -10.0f;
  return camera;
}

const glm::vec3 kMorningSun = sunWorldDirection(46.0, {172.0, 10.0});

TEST(ShadowCascades, GrowGeometricallyFromTheNearestToTheRange) {
  const ShadowCascades c =
      shadowCascades(cameraLookingNorth(), kMorningSun, {50.0f, 1200.0f}, kMapSize);
  EXPECT_FLOAT_EQ(c[0].halfSize_m, 50.0f);
  EXPECT_NEAR(c[1].halfSize_m, std::sqrt(50.0f * 1200.0f), 1e-3f);
  EXPECT_NEAR(c[2].halfSize_m, 1200.0f, 1e-3f);
  // Each map covers 1.5 times its square's half side on the map's 2048 texels.
  EXPECT_NEAR(c[0].mapPixelsPerMetre, kMapSize / (2.0f * 75.0f), 1e-3f);
}

TEST(ShadowCascades, ReachAKilometreAheadAndEachHoldsTheNearerOnesSquare) {
  const Camera camera = cameraLookingNorth();
  const ShadowCascades c = shadowCascades(camera, kMorningSun, {50.0f, 1200.0f}, kMapSize);
  const glm::vec3 north(0.0f, 0.0f, -1.0f), east(1.0f, 0.0f, 0.0f);
  const glm::vec3 ground = camera.position - glm::vec3(0.0f, 20.0f, 0.0f);
  EXPECT_TRUE(inMap(c[2], ground + 1000.0f * north));
  EXPECT_TRUE(inMap(c[2], ground + 1000.0f * north + 500.0f * east));
  EXPECT_FALSE(inMap(c[1], ground + 1000.0f * north));
  // The ground under and just behind the camera is in the finest map.
  EXPECT_TRUE(inMap(c[0], ground));
  EXPECT_TRUE(inMap(c[0], ground - 10.0f * north));
  for (int k = 0; k + 1 < kShadowCascades; ++k)
    for (float sx : {-1.0f, 1.0f})
      for (float sz : {-1.0f, 1.0f}) {
        const glm::vec3 corner = c[k].centre + 0.99f * c[k].halfSize_m * glm::vec3(sx, 0.0f, sz);
        EXPECT_TRUE(inMap(c[k + 1], corner)) << "cascade " << k;
      }
}

// Snapped to whole texels: a world point keeps its place within a texel while the camera
// moves, so shadow edges do not crawl in a fly-through or a time-lapse.
TEST(ShadowCascades, KeepTheirTexelGridFixedInTheWorldAsTheCameraMoves) {
  Camera camera = cameraLookingNorth();
  const glm::vec3 point(530.0f, 300.0f, 700.0f);
  const ShadowCascades before = shadowCascades(camera, kMorningSun, {50.0f, 1200.0f}, kMapSize);
  camera.position += glm::vec3(0.37f, 0.0f, -1.91f);
  const ShadowCascades after = shadowCascades(camera, kMorningSun, {50.0f, 1200.0f}, kMapSize);
  for (int k = 0; k < kShadowCascades; ++k) {
    const glm::vec3 a = mapCoordinates(before[k], point) * float(kMapSize);
    const glm::vec3 b = mapCoordinates(after[k], point) * float(kMapSize);
    for (int axis = 0; axis < 2; ++axis) {
      const double shift = b[axis] - a[axis];
      EXPECT_NEAR(shift, std::round(shift), 0.02) << "cascade " << k << " axis " << axis;
    }
  }
}

// A map holds a caster's shadows where every point of the caster's disc seen from the sun
// falls a texel inside its edge, as shadowAt() (shaders/common.glsl) asks of the points it
// looks up there: then no coarser map need hold the caster.
TEST(ShadowCascades, AMapHoldsTheShadowsOfACasterWhoseDiscLiesInside) {
  const Camera camera = cameraLookingNorth();
  const ShadowCascades c = shadowCascades(camera, kMorningSun, {50.0f, 1200.0f}, kMapSize);
  const float texel = 1.0f / float(kMapSize);
  EXPECT_EQ(shadowHeldBy(c[0], c[0].centre, 10.0f), MapHolds::all);
  EXPECT_EQ(shadowHeldBy(c[0], c[0].centre, 80.0f), MapHolds::some);  // wider than the map
  EXPECT_EQ(shadowHeldBy(c[0], c[1].centre + glm::vec3(0, 0, -200), 5.0f), MapHolds::none);
  EXPECT_EQ(shadowHeldBy(c[2], c[1].centre + glm::vec3(0, 0, -200), 5.0f), MapHolds::all);
  // Crowns of 8 m on a grid over the nearest map and around it: where the map holds one,
  // the points around it, out to its radius across the sun's view, fall a texel inside.
  glm::vec3 right = glm::normalize(glm::cross(-kMorningSun, glm::vec3(0, 1, 0)));
  glm::vec3 up = glm::cross(right, -kMorningSun);
  int held = 0, notHeld = 0;
  for (float x = -120.0f; x <= 120.0f; x += 3.0f)
    for (float z = -120.0f; z <= 120.0f; z += 3.0f) {
      const glm::vec3 centre = c[0].centre + glm::vec3(x, 0.0f, z);
      if (shadowHeldBy(c[0], centre, 8.0f) != MapHolds::all) {
        ++notHeld;
        continue;
      }
      ++held;
      for (float a = 0.0f; a < 6.2832f; a += 0.5f) {
        const glm::vec3 q =
            mapCoordinates(c[0], centre + 8.0f * (std::cos(a) * right + std::sin(a) * up));
        EXPECT_TRUE(q.x >= texel && q.x <= 1.0f - texel && q.y >= texel && q.y <= 1.0f - texel)
            << x << "," << z;
      }
    }
  EXPECT_GT(held, 100);
  EXPECT_GT(notHeld, 100);
}

}  // namespace
}  // namespace eco
