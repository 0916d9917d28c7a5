#include "sim/ecology/plants.hpp"

#include <gtest/gtest.h>

namespace eco {
namespace {

TEST(Plants, ResizeReachesEveryColumn) {
  Plants p;
  p.resize(7);
  std::size_t columns = 0;
  p.forEachColumn([&](const auto& column) {
    EXPECT_EQ(column.size(), 7u);
    ++columns;
  });
  EXPECT_EQ(columns, 17u);
}

TEST(Plants, RemoveDeadKeepsTheOrderOfTheLiving) {
  Plants p;
  p.resize(5);
  for (std::size_t i = 0; i < 5; ++i) {
    p.id[i] = 10 + i;
    p.height_m[i] = static_cast<float>(i);
    p.alive[i] = i % 2 == 0;
  }
  p.removeDead();
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p.id, (std::vector<std::uint64_t>{10, 12, 14}));
  EXPECT_EQ(p.height_m, (std::vector<float>{0.0f, 2.0f, 4.0f}));
  p.forEachColumn([&](const auto& column) { EXPECT_EQ(column.size(), 3u); });
}

}  // namespace
}  // namespace eco
