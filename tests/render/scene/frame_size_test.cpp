#include "render/scene/frame_size.hpp"

#include <gtest/gtest.h>

namespace eco {
namespace {

TEST(FrameSize, ParsesWidthByHeightWithinTheLimits) {
  EXPECT_EQ(parseFrameSize("1280x720"), (FrameSize{1280, 720}));
  EXPECT_EQ(parseFrameSize("16x8192"), (FrameSize{16, 8192}));
  for (const char* bad : {"", "1280", "1280x", "x720", "1280*720", "1280x720x3", "15x100",
                          "100x8193", "-16x16", "12x9000", "1280x720 "})
    EXPECT_FALSE(parseFrameSize(bad).has_value()) << bad;
  EXPECT_EQ(toString(FrameSize{}), "1280x720");
  EXPECT_EQ(parseFrameSize(toString(FrameSize{33, 17})), (FrameSize{33, 17}));
}

}  // namespace
}  // namespace eco
