#include "render/scene/ground_cover.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/frames.hpp"
#include "render/scene/camera.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

// A frustum that holds everything (every plane's test is 0 x + 1 >= 0).
Frustum everywhere() {
  Frustum f;
  f.planes.fill(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  return f;
}

// The eye 1.7 m above the centre of a flat 33 x 33 map of 10 m cells (at 100 m), moved east.
glm::vec3 eyeAt(double east_m) {
  return worldFromMap(160.0 + east_m, 160.0, 101.7);
}

constexpr GroundCoverSettings kNear{.radius_m = 12.0f, .spacing_m = 0.3f};

}  // namespace

TEST(GroundCover, SharesFollowLightMoistureAndSlope) {
  const GroundCoverShares meadow = groundCoverShares(0.0f, 5.0f, 5.0f);
  EXPECT_FLOAT_EQ(meadow.grass, 0.9f);
  EXPECT_FLOAT_EQ(meadow.herb, 0.0f);
  // Under closed crowns no grass, and woodland herbs; most under an open canopy, fewer
  // under the deepest shade.
  const GroundCoverShares closed = groundCoverShares(1.0f, 5.0f, 5.0f);
  const GroundCoverShares open = groundCoverShares(0.6f, 5.0f, 5.0f);
  EXPECT_FLOAT_EQ(closed.grass, 0.0f);
  EXPECT_GT(closed.herb, 0.0f);
  EXPECT_GT(open.herb, 2.0f * closed.herb);
  EXPECT_LT(open.grass, meadow.grass);
  // Dry ground (F 2) bears no grass; F 3 a thin one.
  EXPECT_FLOAT_EQ(groundCoverShares(0.0f, 2.0f, 5.0f).grass, 0.0f);
  const float thin = groundCoverShares(0.0f, 3.0f, 5.0f).grass;
  EXPECT_GT(thin, 0.0f);
  EXPECT_LT(thin, 0.6f * meadow.grass);
  // Rock beyond 50 degrees, as the terrain shows it; a 30 degree slope is a meadow.
  const GroundCoverShares rock = groundCoverShares(0.6f, 5.0f, 55.0f);
  EXPECT_FLOAT_EQ(rock.grass + rock.herb, 0.0f);
  EXPECT_FLOAT_EQ(groundCoverShares(0.0f, 5.0f, 30.0f).grass, meadow.grass);
}

TEST(GroundCover, TuftsStandTallerOnMoisterGround) {
  for (float draw : {0.0f, 0.5f, 0.99f}) {
    EXPECT_LT(groundTuftHeight(GroundPlant::Grass, 3.0f, draw),
              groundTuftHeight(GroundPlant::Grass, 5.0f, draw));
    EXPECT_LT(groundTuftHeight(GroundPlant::Grass, 5.0f, draw),
              groundTuftHeight(GroundPlant::Grass, 8.5f, draw));
    const float herb = groundTuftHeight(GroundPlant::Herb, 5.0f, draw);
    EXPECT_GE(herb, 0.12f);
    EXPECT_LE(herb, 0.24f);
  }
  EXPECT_NEAR(groundTuftHeight(GroundPlant::Grass, 5.0f, 0.0f), 0.25f, 1e-6f);
}

TEST(GroundCover, TuftsStandOnTheGroundWithinTheRadiusAtTheMeadowsDensity) {
  const Terrain terrain = test::flatTerrain(33, 10.0);
  const GroundCover cover(terrain);
  const std::vector<GroundTuft> tufts = cover.scatter(eyeAt(0.0), everywhere(), kNear);
  for (const GroundTuft& t : tufts) {
    EXPECT_LE(glm::distance(t.position, eyeAt(0.0)), kNear.radius_m);
    EXPECT_FLOAT_EQ(t.position.y, 100.0f);
    EXPECT_EQ(t.plant, GroundPlant::Grass);  // open ground
  }
  // The disc within reach of the eye (its radius over the ground 1.7 m below), at 0.9 of
  // the lattice's sites: the count within 3 % (about 4,900 sites, a binomial's 1 %).
  const double reach = std::sqrt(kNear.radius_m * kNear.radius_m - 1.7 * 1.7);
  const double expected =
      0.9 * std::numbers::pi * reach * reach / (kNear.spacing_m * kNear.spacing_m);
  EXPECT_NEAR(static_cast<double>(tufts.size()), expected, 0.03 * expected);
  // From higher than the radius above the ground there are none; just under it, a few.
  EXPECT_TRUE(cover.scatter(worldFromMap(160.0, 160.0, 112.5), everywhere(), kNear).empty());
  EXPECT_FALSE(cover.scatter(worldFromMap(160.0, 160.0, 111.0), everywhere(), kNear).empty());
}

TEST(GroundCover, ATuftStaysWhereItIsAsTheCameraMoves) {
  const Terrain terrain = test::flatTerrain(33, 10.0);
  const GroundCover cover(terrain);
  using Key = std::tuple<float, float>;
  std::map<Key, GroundTuft> seen;
  for (const GroundTuft& t : cover.scatter(eyeAt(0.0), everywhere(), kNear))
    seen[{t.position.x, t.position.z}] = t;
  // 3 m east: every tuft within reach of both eyes is the same tuft.
  std::size_t shared = 0;
  for (const GroundTuft& t : cover.scatter(eyeAt(3.0), everywhere(), kNear)) {
    if (glm::distance(t.position, eyeAt(0.0)) > kNear.radius_m) continue;
    const auto found = seen.find({t.position.x, t.position.z});
    ASSERT_NE(found, seen.end());
    EXPECT_EQ(found->second.height_m, t.height_m);
    EXPECT_EQ(found->second.yaw, t.yaw);
    ++shared;
  }
  EXPECT_GT(shared, seen.size() / 2);
}

TEST(GroundCover, ClosedCrownsLeaveHerbsOnlyAndTheFrustumCullsWhatIsBehind) {
  const Terrain terrain = test::flatTerrain(33, 10.0);
  GroundCover cover(terrain);
  const std::size_t open = cover.scatter(eyeAt(0.0), everywhere(), kNear).size();
  cover.setCanopyCover(Field(terrain.grid.cellCount(), 1.0f));
  const std::vector<GroundTuft> shaded = cover.scatter(eyeAt(0.0), everywhere(), kNear);
  for (const GroundTuft& t : shaded) EXPECT_EQ(t.plant, GroundPlant::Herb);
  // 0.09 of the sites under full shade against 0.9 in the open.
  EXPECT_NEAR(static_cast<double>(shaded.size()) / static_cast<double>(open), 0.1, 0.02);

  // A camera looking east sees none of the tufts west of it.
  cover.setCanopyCover({});
  Camera camera;
  camera.position = eyeAt(0.0);
  camera.yaw_deg = 90.0f;
  camera.pitch_deg = -20.0f;
  const std::vector<GroundTuft> ahead = cover.scatter(
      camera.position, Frustum::fromMatrix(camera.projection(1.0f) * camera.view()), kNear);
  EXPECT_GT(ahead.size(), 0u);
  EXPECT_LT(ahead.size(), open / 3);
  for (const GroundTuft& t : ahead) EXPECT_GT(t.position.x, camera.position.x - 0.5f);
}

TEST(GroundCover, AtlasHasBladesAndLeavesWithTransparentMargins) {
  const Image atlas = makeGroundCoverAtlas();
  ASSERT_EQ(atlas.width, 2 * atlas.height);
  const int half = atlas.height;
  auto coverage = [&](int left) {
    int opaque = 0;
    for (int y = 0; y < half; ++y)
      for (int x = left; x < left + half; ++x) opaque += atlas.get(x, y).a >= 0.5f;
    return static_cast<double>(opaque) / (half * half);
  };
  // Thin blades: a fifth or so of the square; the herb's leaves a little more.
  EXPECT_GT(coverage(0), 0.08);
  EXPECT_LT(coverage(0), 0.4);
  EXPECT_GT(coverage(half), 0.08);
  EXPECT_LT(coverage(half), 0.5);
  // Nothing touches a square's side or top, so mip levels keep the plants apart; the grass
  // stands on the bottom row (the card's foot).
  for (int left : {0, half}) {
    for (int y = 0; y < half; ++y) {
      EXPECT_EQ(atlas.get(left, y).a, 0.0f);
      EXPECT_EQ(atlas.get(left + half - 1, y).a, 0.0f);
    }
    for (int x = left; x < left + half; ++x) EXPECT_EQ(atlas.get(x, half - 1).a, 0.0f);
  }
  int grassFoot = 0;
  for (int x = 0; x < half; ++x) grassFoot += atlas.get(x, 0).a > 0.5f;
  EXPECT_GT(grassFoot, 0);
}

TEST(GroundCover, EachQualityHasItsRadius) {
  EXPECT_EQ(groundCoverFor(RenderQuality::Draft).radius_m, 0.0f);
  EXPECT_GT(groundCoverFor(RenderQuality::Balanced).radius_m, 0.0f);
  EXPECT_GT(groundCoverFor(RenderQuality::High).radius_m,
            groundCoverFor(RenderQuality::Balanced).radius_m);
  const Terrain terrain = test::flatTerrain(33, 10.0);
  EXPECT_TRUE(GroundCover(terrain)
                  .scatter(eyeAt(0.0), everywhere(), groundCoverFor(RenderQuality::Draft))
                  .empty());
}

}  // namespace eco
