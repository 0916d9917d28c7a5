#include "render/gl/gl_objects.hpp"

#include <gtest/gtest.h>

#include "gl_support.hpp"

namespace eco {

TEST(GlObjects, WritePixelsIsTheInverseOfReadPixels) {
  test::useHeadlessGl();
  Image image(7, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x) image.set(x, y, {x / 7.0f, y / 5.0f, 0.5f, 1.0f});
  const RenderTarget target = RenderTarget::create(7, 5);
  writePixels(target, image);
  EXPECT_EQ(readPixels(target).rgba, image.rgba);
}

}  // namespace eco
