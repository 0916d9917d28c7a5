#include "core/image.hpp"

#include <gtest/gtest.h>

namespace eco {

TEST(Image, SetGetRoundsToEightBits) {
  Image image(4, 3);
  image.set(1, 2, {1.0f, 0.5f, 0.0f, 2.0f});  // alpha is clamped
  glm::vec4 c = image.get(1, 2);
  EXPECT_FLOAT_EQ(c.r, 1.0f);
  EXPECT_NEAR(c.g, 0.5f, 1.0f / 255.0f);  // one 8-bit step
  EXPECT_FLOAT_EQ(c.b, 0.0f);
  EXPECT_FLOAT_EQ(c.a, 1.0f);
}

TEST(Image, MeanOpaqueColorIgnoresTransparentPixels) {
  Image image(2, 1);
  image.set(0, 0, {1.0f, 0.0f, 0.0f, 1.0f});
  image.set(1, 0, {0.0f, 0.0f, 1.0f, 0.0f});
  glm::vec4 mean = image.meanOpaqueColor();
  EXPECT_FLOAT_EQ(mean.r, 1.0f);
  EXPECT_FLOAT_EQ(mean.b, 0.0f);
}

TEST(Image, EncodesAValidPng) {
  Image image(16, 8);
  std::vector<std::uint8_t> png = encodePng(image);
  ASSERT_GT(png.size(), 33u);
  const std::uint8_t signature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  EXPECT_TRUE(std::equal(std::begin(signature), std::end(signature), png.begin()));
  // IHDR: width and height, big-endian, at bytes 16..23.
  EXPECT_EQ(png[19], 16);
  EXPECT_EQ(png[23], 8);
}

TEST(Image, RgbDropsAlphaAndKeepsRowOrder) {
  Image image(2, 2);
  image.set(1, 0, {1.0f, 0.0f, 0.0f, 0.0f});
  image.set(0, 1, {0.0f, 0.0f, 1.0f, 1.0f});
  const std::vector<std::uint8_t> rgb = image.rgb();
  ASSERT_EQ(rgb.size(), 12u);
  EXPECT_EQ(rgb[3], 255);  // (1, 0) red, although transparent
  EXPECT_EQ(rgb[8], 255);  // (0, 1) blue
  EXPECT_EQ(rgb[0] + rgb[1] + rgb[2], 0);
}

}  // namespace eco
