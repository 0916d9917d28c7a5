#include "core/angles.hpp"

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

namespace eco {
namespace {

TEST(Angles, ConvertBothWaysAndAgreeWithGlmBitForBit) {
  EXPECT_DOUBLE_EQ(radians(180.0), kPi);
  EXPECT_DOUBLE_EQ(degrees(kPi / 2.0), 90.0);
  EXPECT_FLOAT_EQ(radians(90.0f), static_cast<float>(kPi / 2.0));
  for (double d : {-725.5, -90.0, 0.1, 1.0, 33.3, 85.0, 137.508, 359.99}) {
    EXPECT_EQ(radians(d), glm::radians(d));
    EXPECT_EQ(radians(static_cast<float>(d)), glm::radians(static_cast<float>(d)));
    EXPECT_EQ(degrees(d), glm::degrees(d));
    EXPECT_NEAR(degrees(radians(d)), d, 1e-12 * std::abs(d) + 1e-15);
  }
}

}  // namespace
}  // namespace eco
