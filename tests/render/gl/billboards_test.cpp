#include "render/gl/billboards.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "gl_support.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

// The export's own frames: at 256 pixels every stem is wider than a pixel.
constexpr ImpostorSettings kSmall = kBillboardImpostors;

// Each type's picture is its two views side by side, the tree standing upright in each:
// its stem base is the lowest drawn pixel, where the quad's geometry puts it.
TEST(Billboards, EachPictureShowsTheTreeUprightWhereTheQuadPutsIt) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  const Billboards billboards = bakeBillboards(library, kSmall);
  ASSERT_EQ(billboards.textures.size(), library.types().size());
  const std::array<glm::ivec2, 2> frames = billboardFrames(kSmall.frames);
  for (std::size_t t = 0; t < library.types().size(); ++t) {
    const Image& picture = billboards.textures[t];
    ASSERT_EQ(picture.width, 2 * kSmall.tilePixels);
    ASSERT_EQ(picture.height, kSmall.tilePixels);
    const TreeType& type = library.types()[t];
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

}  // namespace
}  // namespace eco
