#include "sim/run/charts.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/vec3.hpp>

namespace eco {
namespace {

TEST(Charts, TickStepsAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(niceTickStep(100.0), 20.0);
  EXPECT_DOUBLE_EQ(niceTickStep(37.0), 10.0);
  EXPECT_DOUBLE_EQ(niceTickStep(0.9), 0.2);
  EXPECT_DOUBLE_EQ(niceTickStep(2500.0), 500.0);
  EXPECT_DOUBLE_EQ(niceTickStep(0.0), 1.0);
}

bool isColour(glm::vec4 c, glm::vec3 colour) {
  return std::abs(c.r - colour.r) < 0.01f && std::abs(c.g - colour.g) < 0.01f &&
         std::abs(c.b - colour.b) < 0.01f;
}

int pixelsOfColour(const Image& image, glm::vec3 colour) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += isColour(image.get(x, y), colour);
  return n;
}

// The first series is drawn in the palette's blue (0, 0.447, 0.698), the second in its
// vermilion: both lines are there, and the rising one ends higher on the right.
TEST(Charts, ALineChartDrawsEachSeriesInItsColour) {
  LineChart chart{"t", "year", "m", {}, {50.0}};
  chart.series.push_back({"rising", {{0, 0}, {100, 40}}});
  chart.series.push_back({"flat", {{0, 10}, {100, 10}}});
  const Image image = drawLineChart(chart, 600, 400);
  ASSERT_EQ(image.width, 600);
  ASSERT_EQ(image.height, 400);
  const glm::vec3 blue(0.0f, 0.447f, 0.698f), vermilion(0.835f, 0.369f, 0.0f);
  EXPECT_GT(pixelsOfColour(image, blue), 600);  // a 2-pixel line across ~500 pixels
  EXPECT_GT(pixelsOfColour(image, vermilion), 600);
  auto topmost = [&](glm::vec3 colour, int x) {
    for (int y = 0; y < image.height; ++y)
      if (isColour(image.get(x, y), colour)) return y;
    return -1;
  };
  // Near the right end (x 560) the rising line (40) is above the flat one (10).
  EXPECT_LT(topmost(blue, 560), topmost(vermilion, 560));
  EXPECT_GT(topmost(blue, 560), 0);
}

TEST(Charts, SideBySidePutsEachPictureUnderItsCaption) {
  Image red(20, 10), green(20, 10);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x) {
      red.set(x, y, {1, 0, 0, 1});
      green.set(x, y, {0, 1, 0, 1});
    }
  const Image row = sideBySide({red, green}, {"a", "b"});
  ASSERT_EQ(row.width, 40);
  ASSERT_EQ(row.height, 10 + 30);
  EXPECT_EQ(row.get(5, 35), glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(row.get(25, 35), glm::vec4(0, 1, 0, 1));
}

}  // namespace
}  // namespace eco
