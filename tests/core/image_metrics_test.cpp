#include "core/image_metrics.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/random.hpp"

namespace eco {
namespace {

Image noise(int w, int h, std::uint64_t seed) {
  Image image(w, h);
  Rng rng(seed);
  for (auto& byte : image.rgba) byte = static_cast<std::uint8_t>(rng.uniform(0.0, 256.0));
  return image;
}

Image filled(int w, int h, std::uint8_t value) {
  Image image(w, h);
  for (auto& byte : image.rgba) byte = value;
  return image;
}

TEST(ImageMetrics, MeanDifferenceIsThePerChannelAverage) {
  const Image a = filled(8, 4, 100), b = filled(8, 4, 110);
  EXPECT_DOUBLE_EQ(meanAbsoluteDifference(a, b), 10.0);
  EXPECT_DOUBLE_EQ(meanAbsoluteDifference(a, a), 0.0);
  Image c = a;
  c.rgba[0] = 190;  // one channel of one of 32 pixels, off by 90
  EXPECT_DOUBLE_EQ(meanAbsoluteDifference(a, c), 90.0 / (3 * 32));
}

TEST(ImageMetrics, DownsamplingAveragesBlocks) {
  Image image(4, 2);
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 2; ++y) image.set(x, y, glm::vec4(x < 2 ? 0.0f : 1.0f));
  const Image half = downsampled(image, 2);
  ASSERT_EQ(half.width, 2);
  ASSERT_EQ(half.height, 1);
  EXPECT_EQ(half.rgba[0], 0);
  EXPECT_EQ(half.rgba[4], 255);
  // A checkerboard becomes its mean grey.
  Image checker(4, 4);
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y) checker.set(x, y, glm::vec4((x + y) % 2 ? 1.0f : 0.0f));
  EXPECT_EQ(downsampled(checker, 4).rgba[0], 128);
}

TEST(ImageMetrics, SimilarityIsOneForTheSameAndFallsWithNoiseAndStructure) {
  const Image a = noise(64, 48, 1);
  EXPECT_NEAR(structuralSimilarity(a, a), 1.0, 1e-12);
  // Unrelated noise shares no structure.
  EXPECT_LT(std::abs(structuralSimilarity(a, noise(64, 48, 2))), 0.1);
  // A uniform offset of 10 keeps the structure: SSIM stays high, the mean difference is 10.
  Image brighter = a;
  for (auto& byte : brighter.rgba) byte = static_cast<std::uint8_t>(std::min(255, byte + 10));
  EXPECT_GT(structuralSimilarity(a, brighter), 0.95);
  // Flat pictures: identical flat ones are 1, different levels less.
  EXPECT_NEAR(structuralSimilarity(filled(16, 16, 80), filled(16, 16, 80)), 1.0, 1e-12);
  EXPECT_LT(structuralSimilarity(filled(16, 16, 40), filled(16, 16, 200)), 0.5);
}

}  // namespace
}  // namespace eco
