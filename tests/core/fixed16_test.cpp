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

TEST(Fixed16, RoundsToTheNearestStepAsLroundDoes) {
  // Its inline rounding against the C library's: halves away from zero, and a value just
  // below a half (where adding 0.5 would round up) down.
  auto viaLround = [](double value) {
    return static_cast<float>(static_cast<double>(std::lround(value * Fixed16<1>::kStepsPerUnit)) /
                              Fixed16<1>::kStepsPerUnit);
  };
  for (const double steps : {0.5, 1.5, 2.5, 65534.5, std::nextafter(0.5, 0.0),
                             std::nextafter(1.5, 0.0), std::nextafter(0.5, 1.0)}) {
    const double value = steps / Fixed16<1>::kStepsPerUnit;
    EXPECT_EQ(static_cast<float>(Fixed16<1>(value)), viaLround(value)) << steps;
  }
  EXPECT_EQ(static_cast<float>(Fixed16<1>(0.5 / Fixed16<1>::kStepsPerUnit)),
            static_cast<float>(Fixed16<1>::kStep));
  Rng rng(29);
  for (int k = 0; k < 100000; ++k) {
    const double v = rng.uniform();
    ASSERT_EQ(static_cast<float>(Fixed16<1>(v)), viaLround(v)) << v;
  }
}

}  // namespace
}  // namespace eco
