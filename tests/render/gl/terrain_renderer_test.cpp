#include "render/gl/terrain_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "gl_support.hpp"
#include "render/gl/scene_renderer.hpp"
#include "render_support.hpp"
#include "sim/conditions/condition_maps.hpp"

namespace eco {
namespace {

Image renderFromAbove(SceneRenderer& renderer, int size, double altitude_m = 900.0) {
  Camera camera;
  camera.position = worldFromMap(160, 160, altitude_m);
  camera.pitch_deg = -90.0f;
  camera.fovY_deg = 30.0f;
  RenderOptions options;
  options.sun = {172.0, 12.0};
  options.fogDensity = 0.0f;
  const RenderTarget target = RenderTarget::create(size, size);
  renderer.render(nullptr, camera, options, target);
  return readPixels(size, size);
}

TEST(TerrainRenderer, IsOneTrianglePairPerGridSquareAndItsRim) {
  test::useHeadlessGl();
  TerrainRenderer terrain(test::flatTerrain(33, 10.0));
  // The rim: a pair per edge square along each of the four sides, one per corner.
  EXPECT_EQ(terrain.triangleCount(), 32u * 32u * 2u + (4u * 32u + 4u) * 2u);
}

TEST(TerrainRenderer, DrawsOnlyTheChunksInTheFrustum) {
  test::useHeadlessGl();
  TerrainRenderer terrain(test::flatTerrain(129, 10.0));  // 4 x 4 chunks of 32 squares
  Camera camera;
  camera.position = worldFromMap(640, 640, 5000);
  camera.pitch_deg = -90.0f;
  const RenderTarget target = RenderTarget::create(16, 16);
  target.bind();
  EXPECT_EQ(terrain.draw(Frustum::fromMatrix(camera.projection(1.0f) * camera.view()), false),
            terrain.triangleCount());
  camera.pitch_deg = 90.0f;  // looking up at the sky
  EXPECT_EQ(terrain.draw(Frustum::fromMatrix(camera.projection(1.0f) * camera.view()), false), 0u);
  // Low over the south-west corner looking south-west: only the chunks there.
  camera.position = worldFromMap(100, 100, 120);
  camera.yaw_deg = 225.0f;
  camera.pitch_deg = -30.0f;
  camera.fovY_deg = 30.0f;
  const std::size_t corner =
      terrain.draw(Frustum::fromMatrix(camera.projection(1.0f) * camera.view()), false);
  EXPECT_GT(corner, 0u);
  EXPECT_LE(corner, terrain.triangleCount() / 4);
}

TEST(TerrainRenderer, AnOverlayColoursTheGroundByTheMapsRamp) {
  test::useHeadlessGl();
  const Terrain terrain = test::flatTerrain(33, 10.0);
  SceneRenderer renderer(terrain, 46.0, nullptr);
  const Image plain = renderFromAbove(renderer, 64);
  // A field growing from west to east.
  Field field(terrain.grid.cellCount());
  for (int y = 0; y < 33; ++y)
    for (int x = 0; x < 33; ++x) field[terrain.grid.index(x, y)] = static_cast<float>(x);
  renderer.terrain().setOverlay("moisture", field);
  const Image overlay = renderFromAbove(renderer, 64);
  EXPECT_GT(test::compareImages(plain, overlay).mean, 10.0);
  // The west edge takes the ramp's low end, the east edge its high end.
  auto distance = [&](glm::vec4 c, double t) {
    return glm::length(glm::normalize(glm::vec3(c)) - glm::normalize(rampColor("moisture", t)));
  };
  const glm::vec4 west = overlay.get(12, 32), east = overlay.get(51, 32);
  EXPECT_LT(distance(west, 0.0), distance(east, 0.0));
  EXPECT_LT(distance(east, 1.0), distance(west, 1.0));
  renderer.terrain().clearOverlay();
  EXPECT_EQ(test::compareImages(plain, renderFromAbove(renderer, 64)).max, 0);
}

TEST(TerrainRenderer, GroundUnderCrownsIsLeafLitterAndOpenGroundGrass) {
  test::useHeadlessGl();
  const Terrain terrain = test::flatTerrain(33, 10.0);
  SceneRenderer renderer(terrain, 46.0, nullptr);
  // Crowns cover the east half of the map, none the west.
  Field cover(terrain.grid.cellCount(), 0.0f);
  for (int y = 0; y < 33; ++y)
    for (int x = 17; x < 33; ++x) cover[terrain.grid.index(x, y)] = 1.0f;
  renderer.terrain().setCanopyCover(cover);
  const Image image = renderFromAbove(renderer, 64);
  auto meanOver = [&](int x0, int x1) {
    glm::vec3 sum(0.0f);
    for (int y = 8; y < 56; ++y)
      for (int x = x0; x < x1; ++x) sum += glm::vec3(image.get(x, y));
    return sum / static_cast<float>((x1 - x0) * 48);
  };
  const glm::vec3 open = meanOver(4, 24), forest = meanOver(40, 60);
  // Grass is green above red; litter is brown, red above green.
  EXPECT_GT(open.g, 1.2f * open.r);
  EXPECT_GT(forest.r, forest.g);
  // Detail within each: no flat colour (standard deviation of the green over the open half).
  double variance = 0.0;
  for (int y = 8; y < 56; ++y)
    for (int x = 4; x < 24; ++x) variance += std::pow(image.get(x, y).g - open.g, 2.0);
  EXPECT_GT(std::sqrt(variance / (20 * 48)), 0.01);
}

TEST(TerrainRenderer, TheCrownsOfTreesTooSmallToDrawCoverTheGroundInTheirColour) {
  test::useHeadlessGl();
  const Terrain terrain = test::flatTerrain(33, 10.0);
  SceneRenderer renderer(terrain, 46.0, nullptr);
  const Image plain = renderFromAbove(renderer, 64);
  // Blue crowns, three cell areas of them in every cell: of trees under 4 m in the east half,
  // of trees of 16-32 m in the west.
  CanopyFloor floor;
  floor.crownsBelow.resize(terrain.grid.cellCount());
  floor.leafColor.assign(terrain.grid.cellCount(), glm::vec3(0.0f, 0.0f, 0.2f));
  for (int y = 0; y < 33; ++y)
    for (int x = 0; x < 33; ++x) {
      auto& below = floor.crownsBelow[terrain.grid.index(x, y)];
      for (std::size_t b = x >= 17 ? 2 : 5; b < below.size(); ++b) below[b] = 3.0f;
    }
  renderer.terrain().setCanopyFloor(floor);
  // From 800 m up, a tree is a pixel of this 64-pixel frame at 6.7 m: the short trees are
  // not drawn and their crowns cover the east half (95 % of it); the tall ones would be
  // drawn, so the west half is the ground as it was, to the bit.
  const Image far = renderFromAbove(renderer, 64);
  // The ground spans pixels 8-56 of the frame (320 m of 429).
  for (int y = 12; y < 52; ++y) {
    for (int x = 12; x < 28; ++x) ASSERT_EQ(far.get(x, y), plain.get(x, y));
    for (int x = 36; x < 52; ++x) {
      const glm::vec4 c = far.get(x, y);
      ASSERT_GT(c.b, 2.0f * std::max(c.r, c.g));
    }
  }
  // From 150 m up a pixel spans 1.3 m: the short trees are drawn, the ground shows none.
  const Image nearWith = renderFromAbove(renderer, 64, 250.0);
  renderer.terrain().setCanopyFloor(
      CanopyFloor{std::vector<std::array<float, 8>>(terrain.grid.cellCount()),
                  std::vector<glm::vec3>(terrain.grid.cellCount())});
  EXPECT_EQ(test::compareImages(nearWith, renderFromAbove(renderer, 64, 250.0)).max, 0);
}

TEST(TerrainRenderer, DryMeadowsBrownTowardStrawAndWetOnesAreDarkerGreen) {
  test::useHeadlessGl();
  const Terrain terrain = test::flatTerrain(33, 10.0);
  SceneRenderer renderer(terrain, 46.0, nullptr);
  const Image unset = renderFromAbove(renderer, 64);
  // Fresh everywhere (F 5) is the ground without a moisture field.
  renderer.terrain().setMoisture(Field(terrain.grid.cellCount(), 5.0f));
  EXPECT_EQ(test::compareImages(unset, renderFromAbove(renderer, 64)).max, 0);
  // Dry (F 2.5) in the west half, wet (F 8) in the east.
  Field moisture(terrain.grid.cellCount(), 2.5f);
  for (int y = 0; y < 33; ++y)
    for (int x = 17; x < 33; ++x) moisture[terrain.grid.index(x, y)] = 8.0f;
  renderer.terrain().setMoisture(moisture);
  const Image image = renderFromAbove(renderer, 64);
  auto meanOver = [&](const Image& picture, int x0, int x1) {
    glm::vec3 sum(0.0f);
    for (int y = 8; y < 56; ++y)
      for (int x = x0; x < x1; ++x) sum += glm::vec3(picture.get(x, y));
    return sum / static_cast<float>((x1 - x0) * 48);
  };
  const glm::vec3 fresh = meanOver(unset, 4, 24), dry = meanOver(image, 4, 24),
                  wet = meanOver(image, 40, 60);
  // Straw: redder for its green than a fresh meadow; wet: darker and greener for its red.
  EXPECT_GT(dry.r / dry.g, 1.15f * fresh.r / fresh.g);
  EXPECT_LT(wet.r + wet.g, 0.95f * (fresh.r + fresh.g));
  EXPECT_LT(wet.r / wet.g, 0.95f * fresh.r / fresh.g);
}

}  // namespace
}  // namespace eco
