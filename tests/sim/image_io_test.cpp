#include "sim/image_io.hpp"

#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_files.hpp"

namespace eco {

TEST(ImageIo, Sixteen_BitPngGivesTheStoredIntegers) {
  auto dir = test::freshDirectory("imageio16");
  std::vector<std::uint16_t> stored = {0, 1, 40000, 65535};
  writeUint16Image(dir / "h.png", 2, 2, stored);
  SingleChannelImage image = readSingleChannel(dir / "h.png");
  ASSERT_EQ(image.values.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(image.values[i], static_cast<float>(stored[i]));
  EXPECT_DOUBLE_EQ(image.typeMax, 65535.0);
  EXPECT_EQ(test::entriesIn(dir), 1u);  // no temporary left
}

TEST(ImageIo, FloatImagesKeepTheirValues) {
  auto dir = test::freshDirectory("imageiof");
  std::vector<float> metres = {-12.5f, 0.0f, 812.25f, 3000.0f, 1.0f, 2.0f};
  for (const char* name : {"h.exr", "h.tif"}) {
    writeFloatImage(dir / name, 3, 2, 1, metres);
    SingleChannelImage image = readSingleChannel(dir / name);
    EXPECT_EQ(image.width, 3);
    EXPECT_EQ(image.values, metres) << name;
    EXPECT_DOUBLE_EQ(image.typeMax, 1.0);
  }
}

TEST(ImageIo, ColourPicturesComeBackAsRgbaWhateverTheirChannels) {
  auto dir = test::freshDirectory("imageiocolour");
  Image picture(2, 1);
  picture.set(0, 0, {1.0f, 0.0f, 0.2f, 0.5f});
  picture.set(1, 0, {0.0f, 1.0f, 0.4f, 1.0f});
  writeRgba8Image(dir / "rgba.png", picture);
  EXPECT_EQ(readColorImage(dir / "rgba.png").rgba, picture.rgba);
  writeRgb8Image(dir / "rgb.png", picture);  // alpha dropped: opaque when read
  const Image rgb = readColorImage(dir / "rgb.png");
  EXPECT_EQ(rgb.rgba[3], 255);
  EXPECT_EQ(rgb.rgba[4 + 1], 255);
  writeUint16Image(dir / "grey.png", 2, 1, {0, 65535});  // grey: every channel alike
  const Image grey = readColorImage(dir / "grey.png");
  EXPECT_EQ(grey.rgba[4], 255);
  EXPECT_EQ(grey.rgba[6], 255);
  EXPECT_EQ(grey.rgba[0], 0);
  EXPECT_THROW(readColorImage(dir / "missing.png"), InputError);
}

TEST(ImageIo, BadImagesAreInputErrors) {
  auto dir = test::freshDirectory("imageiobad");
  EXPECT_THROW(readSingleChannel(dir / "missing.png"), InputError);
  writeFloatImage(dir / "tiny.exr", 1, 1, 1, {5.0f});
  EXPECT_THROW(readSingleChannel(dir / "tiny.exr"), InputError);
  writeFloatImage(dir / "nan.exr", 2, 2, 1, {1.0f, NAN, 2.0f, 3.0f});
  EXPECT_THROW(readSingleChannel(dir / "nan.exr"), InputError);
  writeRgb8Image(dir / "rgb.png", 2, 2, std::vector<std::uint8_t>(12, 100));
  try {
    readSingleChannel(dir / "rgb.png");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("single-channel"), std::string::npos);
  }
  std::ofstream(dir / "garbage.png") << "not an image";
  EXPECT_THROW(readSingleChannel(dir / "garbage.png"), InputError);
  EXPECT_THROW(writeFloatImage("/nonexistent/x.exr", 2, 2, 1, {1, 2, 3, 4}), InputError);
}

// A 17-byte bitmap claiming 52,232,255 x 5 pixels (the fuzzer's find): refused from its
// header, where reading it made OpenImageIO allocate 13 GB.
TEST(ImageIo, AnImageWiderThanTheLimitIsRefusedFromItsHeader) {
  auto dir = test::freshDirectory("imageiowide");
  std::ofstream(dir / "wide.pgm", std::ios::binary) << "P452232255\n 5\n52";
  try {
    readSingleChannel(dir / "wide.pgm");
    FAIL() << "read a 52-million-pixel-wide image";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("52232255 x 5 pixels; ecoforest reads heightmaps of "
                        "at most 16384 x 16384"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace eco
