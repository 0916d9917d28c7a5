#include "sim/grid.hpp"

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

TEST(Grid, Stats) {
  FieldStats s = statsOf({1.0f, 2.0f, 6.0f});
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_DOUBLE_EQ(s.max, 6.0);
}

}  // namespace eco
