#include "render/gl/ground_cover_renderer.hpp"

#include <gtest/gtest.h>

#include "core/frames.hpp"
#include "gl_support.hpp"
#include "render/gl/scene_renderer.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

constexpr int kWidth = 160, kHeight = 90;

// A person's view over a flat 330 m square of open ground, looking east and a little down.
Camera eyeLevel() {
  return test::cameraAt(worldFromMap(100.0, 160.0, 101.7), 90.0f, -10.0f);
}

struct Drawn {
  Image image;
  FrameStats stats;
};

Drawn draw(SceneRenderer& renderer, float radius_m) {
  RenderOptions options;
  options.sun = {172.0, 12.0};
  options.groundCover.radius_m = radius_m;
  const RenderTarget target = RenderTarget::create(kWidth, kHeight);
  const FrameStats stats = renderer.render(nullptr, eyeLevel(), options, target);
  return {readPixels(kWidth, kHeight), stats};
}

// Mean difference over the rows of the picture below the horizon's band (the ground).
double groundDifference(const Image& a, const Image& b) {
  double sum = 0.0;
  for (int y = kHeight / 2 + 8; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      sum += glm::length(glm::vec3(a.get(x, y)) - glm::vec3(b.get(x, y)));
  return 255.0 * sum / (kWidth * (kHeight - kHeight / 2 - 8));
}

}  // namespace

TEST(GroundCoverRenderer, DrawsGrassOverTheOpenGroundAndHerbsUnderCrowns) {
  test::useHeadlessGl();
  const Terrain terrain = test::flatTerrain(33, 10.0);
  SceneRenderer renderer(terrain, 46.0, nullptr);
  const Drawn bare = draw(renderer, 0.0f);
  const Drawn meadow = draw(renderer, 20.0f);
  EXPECT_EQ(bare.stats.groundTufts, 0u);
  // The tufts drawn are those the scatter gives for this camera and its frustum.
  const Camera camera = eyeLevel();
  const Frustum frustum =
      Frustum::fromMatrix(camera.projection(static_cast<float>(kWidth) / kHeight) * camera.view());
  const std::size_t scattered =
      renderer.groundCover().scatter(camera.position, frustum, {.radius_m = 20.0f}).size();
  EXPECT_EQ(meadow.stats.groundTufts, scattered);
  EXPECT_GT(scattered, 1000u);
  // They change the near ground (blades standing against it, lit and shadowed), not the sky.
  EXPECT_GT(groundDifference(bare.image, meadow.image), 8.0);
  for (int x = 0; x < kWidth; ++x) EXPECT_EQ(bare.image.get(x, 2), meadow.image.get(x, 2));

  // Under closed crowns the herbs are a tenth as many, and the ground changes less.
  renderer.groundCover().setCanopyCover(Field(terrain.grid.cellCount(), 1.0f));
  const Drawn shaded = draw(renderer, 20.0f);
  EXPECT_LT(shaded.stats.groundTufts, scattered / 5);
  EXPECT_GT(shaded.stats.groundTufts, 0u);
  EXPECT_LT(groundDifference(bare.image, shaded.image),
            0.5 * groundDifference(bare.image, meadow.image));
}

TEST(GroundCoverRenderer, IsTheSameFrameEachTime) {
  test::useHeadlessGl();
  const Terrain terrain = test::flatTerrain(33, 10.0);
  SceneRenderer renderer(terrain, 46.0, nullptr);
  const Drawn first = draw(renderer, 20.0f);
  const Drawn again = draw(renderer, 20.0f);
  EXPECT_EQ(test::compareImages(first.image, again.image).max, 0);
}

}  // namespace eco
