#include "core/fixed16.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/random.hpp"

namespace eco {
namespace {

TEST(Fixed16, KeepsItsRangeToHalfAStep) {
  // The ends are kept exactly, and every value within half a step of 1/65,535 of the range.
  EXPECT_EQ(static_cast<float>(Fixed16<1>(0.0)), 0.0f);
  EXPECT_EQ(static_cast<float>(Fixed16<1>(1.0)), 1.0f);
  EXPECT_EQ(static_cast<float>(Fixed16<4>(4.0)), 4.0f);
  Rng rng(17);
  for (int k = 0; k < 10000; ++k) {
    const double v = rng.uniform();
    EXPECT_NEAR(static_cast<float>(Fixed16<1>(v)), v, 0.5 * Fixed16<1>::kStep + 1e-7);
    EXPECT_NEAR(static_cast<float>(Fixed16<4>(4.0 * v)), 4.0 * v, 0.5 * Fixed16<4>::kStep + 1e-6);
  }
  // Beyond the range its nearest end; not a number, 0.
  EXPECT_EQ(static_cast<float>(Fixed16<1>(1.5)), 1.0f);
  EXPECT_EQ(static_cast<float>(Fixed16<1>(-0.25)), 0.0f);
  EXPECT_EQ(static_cast<float>(Fixed16<4>(std::nan(""))), 0.0f);
  EXPECT_EQ(static_cast<float>(Fixed16<4>(1e30)), 4.0f);
  EXPECT_EQ(sizeof(Fixed16<1>), 2u);
}

}  // namespace
}  // namespace eco
