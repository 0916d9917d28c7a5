#include "render/scene/culling.hpp"
#include "core/angles.hpp"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace eco {
namespace {

TEST(Frustum, KeepsSpheresInsideOrTouchingAndDropsThoseOutside) {
  // Looking down -z from the origin, 90 degrees, near 1, far 100.
  const glm::mat4 m = glm::perspective(radians(90.0f), 1.0f, 1.0f, 100.0f);
  const Frustum f = Frustum::fromMatrix(m);
  EXPECT_TRUE(f.intersectsSphere({0, 0, -10}, 0.5f));
  EXPECT_FALSE(f.intersectsSphere({0, 0, 10}, 0.5f));     // behind
  EXPECT_FALSE(f.intersectsSphere({0, 0, -150}, 10.0f));  // beyond far
  EXPECT_FALSE(f.intersectsSphere({-20, 0, -10}, 5.0f));  // left of the 45-degree plane
  // The left plane is x = z; a sphere centred 2 m outside it (perpendicular 2/sqrt(2) m)
  // touches it from radius 1.42 on.
  EXPECT_FALSE(f.intersectsSphere({-12, 0, -10}, 1.40f));
  EXPECT_TRUE(f.intersectsSphere({-12, 0, -10}, 1.45f));
}

// A box is outside only where every sphere within it is, inside only where every sphere
// centred in it is: checked against intersectsSphere on a lattice of spheres in each box.
TEST(Frustum, PlacesABoxAsEverySphereInItIsPlaced) {
  const Frustum f = Frustum::fromMatrix(glm::perspective(radians(90.0f), 1.0f, 1.0f, 100.0f));
  using Side = Frustum::Side;
  EXPECT_EQ(f.sideOfBox({-1, -1, -12}, {1, 1, -8}, 0.05f), Side::Inside);
  EXPECT_EQ(f.sideOfBox({-1, -1, 8}, {1, 1, 12}, 0.05f), Side::Outside);       // behind
  EXPECT_EQ(f.sideOfBox({-30, -1, -12}, {-25, 1, -8}, 0.05f), Side::Outside);  // left
  EXPECT_EQ(f.sideOfBox({-15, -1, -12}, {-5, 1, -8}, 0.05f), Side::Across);    // on the left plane
  EXPECT_EQ(f.sideOfBox({-1, -1, -1.02f}, {1, 1, -0.5f}, 0.05f),
            Side::Across);  // on the near plane
  // Every sphere of radius 0.5 in a box (its centre at least 0.5 inside), and every sphere
  // centred in it, placed as the box is.
  for (const auto& [lo, hi] : {std::pair{glm::vec3(-1, -1, -12), glm::vec3(1, 1, -8)},
                               std::pair{glm::vec3(-30, -1, -12), glm::vec3(-25, 1, -8)}}) {
    const Side side = f.sideOfBox(lo, hi, 0.05f);
    for (float x = 0.0f; x <= 1.0f; x += 0.25f)
      for (float z = 0.0f; z <= 1.0f; z += 0.25f) {
        const glm::vec3 within = glm::mix(lo + 0.5f, hi - 0.5f, glm::vec3(x, 0.5f, z));
        const glm::vec3 centred = glm::mix(lo, hi, glm::vec3(x, 0.5f, z));
        if (side == Side::Outside) {
          EXPECT_FALSE(f.intersectsSphere(within, 0.5f));
        }
        if (side == Side::Inside) {
          EXPECT_TRUE(f.intersectsSphere(centred, 0.5f));
        }
      }
  }
}

TEST(LodChoice, FollowsProjectedSizeThroughEveryLevel) {
  LodSettings s;
  // Halfway between switches, in no fade band.
  EXPECT_EQ(chooseLevel(2.0f * s.switchPixels[0], s).level, 0);
  EXPECT_EQ(chooseLevel(0.5f * (s.switchPixels[0] + s.switchPixels[1]), s).level, 1);
  EXPECT_EQ(chooseLevel(0.5f * (s.switchPixels[1] + s.switchPixels[2]), s).level, 2);
  EXPECT_EQ(chooseLevel(0.5f * s.switchPixels[2], s).level, kLevelImpostor);
  EXPECT_EQ(chooseLevel(0.5f, s).level, -1);  // under a pixel: not drawn
  s.impostors = false;
  EXPECT_EQ(chooseLevel(20.0f, s).level, 2);
  EXPECT_EQ(chooseLevel(s.switchPixels[2], s).fadeTo, -1);
  s.forcedLevel = 0;
  EXPECT_EQ(chooseLevel(3.0f, s).level, 0);
}

TEST(RenderQuality, NamesRoundTripAndUnknownOnesAreRefused) {
  for (RenderQuality q : {RenderQuality::Draft, RenderQuality::Balanced, RenderQuality::High})
    EXPECT_EQ(parseRenderQuality(toString(q)), q);
  EXPECT_FALSE(parseRenderQuality("ultra"));
  EXPECT_FALSE(parseRenderQuality(""));
}

TEST(RenderQuality, HigherQualityDrawsEveryLevelFromSmallerSizesOn) {
  const auto draft = switchPixelsFor(RenderQuality::Draft);
  const auto balanced = switchPixelsFor(RenderQuality::Balanced);
  const auto high = switchPixelsFor(RenderQuality::High);
  for (int level = 0; level < 3; ++level) {
    EXPECT_GT(draft[level], balanced[level]);
    EXPECT_GT(balanced[level], high[level]);
  }
  // None draws the crown hulls: LOD2 has no range of its own at any quality.
  for (const auto& sizes : {draft, balanced, high}) {
    LodSettings s;
    s.switchPixels = sizes;
    for (float px = 2000.0f; px > 1.0f; px *= 0.98f) ASSERT_NE(chooseLevel(px, s).level, 2) << px;
  }
  // High keeps LOD0 for every tree taller than about 150 pixels (the promise for
  // stills): fully above the fade band, and at no size below it.
  LodSettings s;
  s.switchPixels = high;
  EXPECT_EQ(chooseLevel(150.0f * (1.0f + s.fadeBand), s).level, 0);
  EXPECT_EQ(chooseLevel(150.0f * (1.0f + s.fadeBand), s).fadeTo, -1);
  EXPECT_EQ(chooseLevel(120.0f, s).level, 1);
}

TEST(LodChoice, AnEmptyLevelIsSkippedAndItsNeighboursFadeIntoEachOther) {
  LodSettings s;
  s.switchPixels = {150.0f, 60.0f, 60.0f};  // LOD2 has no range of its own
  for (float px = 200.0f; px > 0.5f; px *= 0.97f) {
    const LodChoice c = chooseLevel(px, s);
    ASSERT_NE(c.level, 2) << px;
    ASSERT_NE(c.fadeTo, 2) << px;
  }
  const LodChoice middle = chooseLevel(60.0f, s);
  EXPECT_EQ(middle.level, 1);
  EXPECT_EQ(middle.fadeTo, kLevelImpostor);
  EXPECT_NEAR(middle.fade, 0.5f, 1e-5f);
  EXPECT_EQ(chooseLevel(40.0f, s).level, kLevelImpostor);
  // Without impostors the coarsest mesh is never skipped: it takes every size below LOD1.
  s.impostors = false;
  EXPECT_EQ(chooseLevel(60.0f, s).fadeTo, 2);
  EXPECT_EQ(chooseLevel(20.0f, s).level, 2);
}

TEST(LodChoice, CrossFadesContinuouslyAcrossEachSwitch) {
  const LodSettings s;
  for (int level = 0; level < 3; ++level) {
    const float at = s.switchPixels[level];
    const LodChoice middle = chooseLevel(at, s);
    EXPECT_EQ(middle.level, level);
    EXPECT_EQ(middle.fadeTo, level + 1);
    EXPECT_NEAR(middle.fade, 0.5f, 1e-5f);
    // The fade share grows as the tree shrinks, from 0 at the band's top to 1 at its bottom.
    float previous = -1.0f;
    for (float px = at * 1.149f; px > at * 0.851f; px -= at * 0.01f) {
      const LodChoice c = chooseLevel(px, s);
      ASSERT_EQ(c.fadeTo, level + 1);
      EXPECT_GT(c.fade, previous);
      previous = c.fade;
    }
    EXPECT_GT(previous, 0.95f);
    EXPECT_EQ(chooseLevel(at * 1.16f, s).fadeTo, -1);
    EXPECT_EQ(chooseLevel(at * 0.84f, s).level, level + 1);
  }
}

TEST(LodChoice, ProjectedSizeIsInverseInDistance) {
  EXPECT_FLOAT_EQ(projectedPixels(20.0f, 100.0f, 500.0f), 100.0f);
  EXPECT_FLOAT_EQ(projectedPixels(20.0f, 200.0f, 500.0f), 50.0f);
}

// A tree may reach minPixels out to a thousandth beyond the distance where it is exactly
// minPixels tall (room for the renderer's roundings), not a hundredth; and always where a
// level is forced on every tree.
TEST(LodChoice, ATreeMayReachMinPixelsWithinAThousandthOfItsDistance) {
  LodSettings lod;
  lod.minPixels = 2.0f;
  const float reach = 20.0f * 500.0f / 2.0f;  // a 20 m tree is 2 pixels 5 km away
  EXPECT_TRUE(mayReachMinPixels(20.0f, reach, 500.0f, lod));
  EXPECT_TRUE(mayReachMinPixels(20.0f, 1.0009f * reach, 500.0f, lod));
  EXPECT_TRUE(tooSmallToDraw(projectedPixels(20.0f, 1.0009f * reach, 500.0f), lod));
  EXPECT_FALSE(mayReachMinPixels(20.0f, 1.01f * reach, 500.0f, lod));
  lod.forcedLevel = 2;
  EXPECT_TRUE(mayReachMinPixels(20.0f, 100.0f * reach, 500.0f, lod));
}

}  // namespace
}  // namespace eco
