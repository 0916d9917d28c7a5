#include "render/gl/billboards.hpp"

#include <numeric>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "gl_support.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

// The export's own frames: at 256 pixels every stem is wider than a pixel.
const ImpostorSettings kSmall = kBillboardImpostors;

// Each type's picture is its two views side by side, the tree standing upright in each:
// its stem base is the lowest drawn pixel, where the quad's geometry puts it.
TEST(Billboards, EachPictureShowsTheTreeUprightWhereTheQuadPutsIt) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  std::vector<int> every(library.typeCount());
  std::iota(every.begin(), every.end(), 0);
  const Billboards billboards = bakeBillboards(library, every, kSmall);
  ASSERT_EQ(billboards.textures.size(), every.size());
  const std::array<glm::ivec2, 2> frames = billboardFrames(kSmall.frames);
  for (const int t : every) {
    const Image& picture = billboards.textures[t];
    ASSERT_EQ(picture.width, 2 * kSmall.tilePixels);
    ASSERT_EQ(picture.height, kSmall.tilePixels);
    const TreeType& type = library.type(t);
    for (int view = 0; view < 2; ++view) {
      SCOPED_TRACE(testing::Message() << "type " << t << ", view " << view);
      // The stem base (the tree frame's origin) in the view's picture.
      const glm::vec3 f = frameDirection(frames[view], kSmall.frames);
      glm::vec3 right, up;
      frameAxes(f, right, up);
      const glm::vec3 base = -glm::vec3(type.bounds) / type.bounds.w;
      const float baseX = 0.5f * (glm::dot(base, right) + 1.0f) * kSmall.tilePixels;
      const float baseY = (1.0f - 0.5f * (glm::dot(base, up) + 1.0f)) * kSmall.tilePixels;
      int lowest = -1, lowestX = 0, opaque = 0;
      for (int y = 0; y < picture.height; ++y)
        for (int x = 0; x < kSmall.tilePixels; ++x)
          if (picture.get(view * kSmall.tilePixels + x, y).a > 0.5f) {
            ++opaque;
            if (y > lowest) lowest = y, lowestX = x;
          }
      ASSERT_GT(opaque, 20) << "the tree is drawn";
      EXPECT_LT(opaque, kSmall.tilePixels * kSmall.tilePixels / 2) << "and the sky is empty";
      EXPECT_NEAR(lowest, baseY, 4.0f);
      EXPECT_NEAR(lowestX, baseX, 4.0f);
    }
  }
}

TEST(Billboards, OnlyTheTypesAskedForArePictured) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  const std::vector<int> asked{1};
  const Billboards billboards = bakeBillboards(library, asked, kSmall);
  ASSERT_EQ(billboards.textures.size(), static_cast<std::size_t>(library.typeCount()));
  for (int t = 0; t < library.typeCount(); ++t)
    EXPECT_EQ(billboards.textures[t].width, t == 1 ? 2 * kSmall.tilePixels : 0) << t;
}

}  // namespace
}  // namespace eco
