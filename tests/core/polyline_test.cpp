#include "core/polyline.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace eco {

TEST(Polyline, InterpolatesLinearly) {
  Polyline p({{0.0, 1.0}, {7.5, 0.45}, {15.0, 1.0}});  // the beech's m^g
  EXPECT_DOUBLE_EQ(p(0.0), 1.0);
  EXPECT_DOUBLE_EQ(p(7.5), 0.45);
  EXPECT_DOUBLE_EQ(p(15.0), 1.0);
  EXPECT_NEAR(p(3.75), 0.725, 1e-12);
  EXPECT_NEAR(p(10.0), 0.45 + 0.55 * (2.5 / 7.5), 1e-12);
}

TEST(Polyline, ClampsOutsideItsControlPoints) {
  Polyline p({{2.0, 3.0}, {4.0, 5.0}});
  EXPECT_DOUBLE_EQ(p(-10.0), 3.0);
  EXPECT_DOUBLE_EQ(p(1.999), 3.0);
  EXPECT_DOUBLE_EQ(p(4.0), 5.0);
  EXPECT_DOUBLE_EQ(p(100.0), 5.0);
}

TEST(Polyline, VerticalStepLikeThePinesKsW) {
  Polyline p({{0, 1}, {42.89, 1.005}, {42.89, 0.654}, {50, 0.6256}});
  EXPECT_NEAR(p(42.0), 1.0 + 0.005 * 42.0 / 42.89, 1e-12);  // before the step
  EXPECT_NEAR(p(42.89), 0.654, 1e-12);                      // at it: the value after
  EXPECT_NEAR(p(43.0), 0.654 + (0.6256 - 0.654) * (0.11 / 7.11), 1e-12);
  EXPECT_NEAR(p(42.8899), 1.005, 1e-6);
}

TEST(Polyline, RealAbscissaeAndSinglePoint) {
  Polyline p({{0.3875, 34.62}, {1.034, -4.265}});
  EXPECT_NEAR(p(1.0), 34.62 + (1.0 - 0.3875) / (1.034 - 0.3875) * (-4.265 - 34.62), 1e-9);
  EXPECT_DOUBLE_EQ(Polyline::constant(2.5)(-3.0), 2.5);
  EXPECT_DOUBLE_EQ(Polyline::constant(2.5)(1e9), 2.5);
}

TEST(Polyline, RejectsUnsortedPoints) {
  EXPECT_THROW(Polyline({{1.0, 0.0}, {0.5, 1.0}}), InternalError);
  EXPECT_THROW(Polyline(std::vector<ControlPoint>{}), InternalError);
}

}  // namespace eco
