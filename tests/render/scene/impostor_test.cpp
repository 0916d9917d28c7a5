#include "render/scene/impostor.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

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

// Frames show the quality's level, but a species that bears needles shows LOD0 at every
// quality: its LOD1 gathers the needles into cluster cards (render/gl's
// Impostor.OfAPineCoversWhatItsNeedlesCover measures why).
TEST(Impostor, ASpeciesThatBearsNeedlesBakesItsFramesFromLod0) {
  const Species pine = test::namedLibrarySpecies("pine").model;
  const Species beech = test::namedLibrarySpecies("beech").model;
  for (RenderQuality quality :
       {RenderQuality::Draft, RenderQuality::Balanced, RenderQuality::High}) {
    const int bakeLod = impostorSettingsFor(quality).bakeLod;
    EXPECT_EQ(impostorBakeLevel(pine, bakeLod), 0);
    EXPECT_EQ(impostorBakeLevel(beech, bakeLod), bakeLod);
  }
  EXPECT_EQ(impostorSettingsFor(RenderQuality::Balanced).bakeLod, 1);
}

// Two by two frames of 8 texels (rows as OpenGL reads them, bottom up): each frame's reach
// is the farthest corner of its covered texels from its centre, in half sides.
TEST(Impostor, EachFramesExtentIsTheFarthestCornerOfItsCoveredTexels) {
  const int frames = 2, tile = 8, side = frames * tile;
  std::vector<std::uint8_t> alpha(side * side, 0);
  auto cover = [&](int column, int row, int x, int y, std::uint8_t a) {
    alpha[(row * tile + y) * side + column * tile + x] = a;
  };
  cover(0, 0, 4, 4, 255);  // the texel just past the centre: its far corner 1 texel out
  cover(0, 0, 3, 3, 1);    // the one just before it, as faintly covered as can be
  cover(1, 0, 0, 5, 40);   // the frame's left edge
  cover(1, 1, 6, 1, 255);  // 3 texels below the centre at its far corner, 3 right of it
  // frame (0, 1) stays empty
  const std::vector<float> extents = frameExtents(alpha, frames, tile);
  ASSERT_EQ(extents.size(), 4u);
  EXPECT_FLOAT_EQ(extents[0], 0.25f);  // (column 0, row 0)
  EXPECT_FLOAT_EQ(extents[1], 1.0f);   // (1, 0)
  EXPECT_FLOAT_EQ(extents[2], 0.0f);   // (0, 1)
  EXPECT_FLOAT_EQ(extents[3], 0.75f);  // (1, 1)
}

}  // namespace
}  // namespace eco
