#include "render/impostor.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "render/scene_renderer.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

TEST(Impostor, TheHemiOctahedralMapRoundTrips) {
  for (float azimuth = 0.0f; azimuth < 6.28f; azimuth += 0.37f)
    for (float elevation = 0.0f; elevation <= 1.5708f; elevation += 0.19f) {
      const glm::vec3 d(std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                        std::cos(elevation) * std::sin(azimuth));
      const glm::vec2 uv = hemiOctEncode(d);
      EXPECT_GE(uv.x, -1e-6f);
      EXPECT_LE(uv.x, 1.0f + 1e-6f);
      EXPECT_LT(glm::distance(hemiOctDecode(uv), d), 1e-5f);
    }
}

TEST(Impostor, EachFrameIsChosenFromItsOwnDirectionAndItsAxesAreOrthonormal) {
  const int frames = 8;
  for (int row = 0; row < frames; ++row)
    for (int column = 0; column < frames; ++column) {
      const glm::vec3 f = frameDirection({column, row}, frames);
      EXPECT_EQ(impostorFrame(f, frames), glm::ivec2(column, row));
      glm::vec3 right, up;
      frameAxes(f, right, up);
      EXPECT_NEAR(glm::dot(right, f), 0.0f, 1e-5f);
      EXPECT_NEAR(glm::dot(up, f), 0.0f, 1e-5f);
      EXPECT_NEAR(glm::dot(right, up), 0.0f, 1e-5f);
      EXPECT_NEAR(glm::length(glm::cross(right, up) - f), 0.0f, 1e-5f);
    }
  // Seen from below the horizon, a tree shows its horizon frame.
  EXPECT_EQ(impostorFrame({1, -0.5f, 0}, frames), impostorFrame({1, 0, 0}, frames));
}

// At its switching size the impostor stands in for the meshes: the mature maple rendered at
// 60 pixels high as LOD0 and as its impostor, compared as a whole, since single leaves fall
// on different pixels. Tolerances: the two cover the same number of pixels to within 20 %
// (leaf cards flicker in and out at this size), and their mean colours over the tree differ
// by less than 20 of 255 (RMS over the channels; the impostor shows LOD1's clustered leaves
// from up to 11 degrees off, out of 64-pixel tiles).
TEST(Impostor, MatchesTheMeshAtTheSwitchingDistance) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(33, 10.0);
  SceneRenderer renderer(terrain, 46.0, &library);
  const int type = library.typeIndex(1, 0, 1);
  const float height = library.types()[type].height_m;
  Forest forest;
  forest.add(library, type, worldFromMap(160, 160, 100), height, 0.0f, 1.0f, 1);
  Camera camera;
  RenderOptions options;
  options.shadows = false;
  const int size = 128;
  const float distance = height * camera.pixelsPerRadian(size) / LodSettings{}.switchPixels[2];
  camera.position = worldFromMap(160, 160 - distance, 100 + 0.5 * height);
  const RenderTarget target = RenderTarget::create(size, size);
  Forest empty;
  renderer.render(&empty, camera, options, target);
  const Image background = readPixels(size, size);
  options.lod.forcedLevel = 0;
  renderer.render(&forest, camera, options, target);
  const Image mesh = readPixels(size, size);
  options.lod.forcedLevel = kLevelImpostor;
  renderer.render(&forest, camera, options, target);
  const Image impostor = readPixels(size, size);

  // The tree's pixels: where the image differs from the empty scene.
  auto treePixels = [&](const Image& image, glm::dvec3& meanColor) {
    std::size_t count = 0;
    meanColor = glm::dvec3(0.0);
    for (std::size_t p = 0; p < image.rgba.size(); p += 4) {
      bool differs = false;
      for (int c = 0; c < 3; ++c)
        differs = differs || std::abs(int(image.rgba[p + c]) - int(background.rgba[p + c])) > 8;
      if (!differs) continue;
      ++count;
      meanColor += glm::dvec3(image.rgba[p], image.rgba[p + 1], image.rgba[p + 2]);
    }
    meanColor /= std::max<double>(count, 1.0);
    return count;
  };
  glm::dvec3 meshColor, impostorColor;
  const std::size_t meshPixels = treePixels(mesh, meshColor);
  const std::size_t impostorPixels = treePixels(impostor, impostorColor);
  ASSERT_GT(meshPixels, 300u);  // the tree is there and about 60 pixels high
  const double coverageDifference =
      std::abs(double(meshPixels) - double(impostorPixels)) / double(meshPixels);
  EXPECT_LT(coverageDifference, 0.20) << meshPixels << " vs " << impostorPixels;
  const double colorDifference = glm::length(meshColor - impostorColor) / std::sqrt(3.0);
  EXPECT_LT(colorDifference, 20.0)
      << "mesh " << meshColor.r << "," << meshColor.g << "," << meshColor.b << " impostor "
      << impostorColor.r << "," << impostorColor.g << "," << impostorColor.b;
  if (test::updatingReferences()) {
    test::writePng("/tmp/impostor_mesh.png", mesh);
    test::writePng("/tmp/impostor_impostor.png", impostor);
  }
}

}  // namespace
}  // namespace eco
