#include "sim/grid.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace eco {

TEST(Grid, IndexingAndArea) {
  Grid g{4, 3, 10.0, 20.0};
  EXPECT_EQ(g.cellCount(), 12u);
  EXPECT_EQ(g.index(3, 2), 11u);
  EXPECT_TRUE(g.contains(0, 0));
  EXPECT_FALSE(g.contains(4, 0));
  EXPECT_FALSE(g.contains(0, -1));
  EXPECT_DOUBLE_EQ(g.area_m2(), 12 * 200.0);
}

TEST(Grid, ThePlaceOfAPositionIsItsColumnAndRow) {
  const Grid g{4, 3, 10.0, 20.0};  // centres at east 0..30, north 0..40; row 0 the northmost
  EXPECT_EQ(g.cellAt(0.0, 40.0), 0);
  EXPECT_EQ(g.cellAt(34.9, -9.9), static_cast<long>(g.index(3, 2)));
  EXPECT_EQ(g.columnAt(14.9), 1);
  EXPECT_EQ(g.columnAt(15.0), 2);
  EXPECT_EQ(g.rowAt(30.1), 0);
  EXPECT_EQ(g.rowAt(29.9), 1);
  // Outside: -1, for the cell when either part is.
  EXPECT_EQ(g.columnAt(-5.1), -1);
  EXPECT_EQ(g.columnAt(35.0), -1);
  EXPECT_EQ(g.rowAt(50.1), -1);
  EXPECT_EQ(g.rowAt(std::nan("")), -1);
  EXPECT_EQ(g.cellAt(-5.1, 20.0), -1);
  EXPECT_EQ(g.cellAt(10.0, 50.1), -1);
  for (double east = -8.0; east < 40.0; east += 0.7)
    for (double north = -14.0; north < 56.0; north += 1.1) {
      const int x = g.columnAt(east), y = g.rowAt(north);
      EXPECT_EQ(g.cellAt(east, north), x < 0 || y < 0 ? -1 : static_cast<long>(g.index(x, y)));
    }
}

TEST(Grid, Stats) {
  FieldStats s = statsOf({1.0f, 2.0f, 6.0f});
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_DOUBLE_EQ(s.max, 6.0);
}

TEST(Grid, SampleBilinearIsExactForAPlaneAndClampsAtTheEdges) {
  // A plane v = 2 east + 3 north + 1 on 4 x 3 cells of 10 x 20 m: bilinear interpolation
  // reproduces it anywhere between the cell centres.
  Grid g{4, 3, 10.0, 20.0};
  Field plane(g.cellCount());
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x)
      plane[g.index(x, y)] = static_cast<float>(2.0 * g.eastOf(x) + 3.0 * g.northOf(y) + 1.0);
  for (double east : {0.0, 4.0, 15.5, 30.0})
    for (double north : {0.0, 7.0, 33.0, 40.0})
      EXPECT_NEAR(sampleBilinear(g, plane, east, north), 2.0 * east + 3.0 * north + 1.0, 1e-3);
  // Beyond the outer centres: the edge's value.
  EXPECT_NEAR(sampleBilinear(g, plane, -5.0, 50.0), sampleBilinear(g, plane, 0.0, 40.0), 1e-4);
  EXPECT_NEAR(sampleBilinear(g, plane, 99.0, -9.0), sampleBilinear(g, plane, 30.0, 0.0), 1e-4);
}

}  // namespace eco
