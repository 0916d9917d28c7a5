#include "render/scene/forest_cache.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace eco {
namespace {

// A forest of `trees` trees.
Forest forestOfSize(std::size_t trees) {
  Forest forest;
  forest.resize(trees);
  return forest;
}

// Year y's forest has 1000 y trees; each read is counted.
struct CountedLoads {
  std::vector<int> years;
  ForestCache::Load load() {
    return [this](int year) {
      years.push_back(year);
      return forestOfSize(static_cast<std::size_t>(year) * 1000);
    };
  }
};

TEST(ForestCache, AYearIsReadOnceWhileItFitsTheBudget) {
  CountedLoads loads;
  ForestCache cache(loads.load(), std::uint64_t{1} << 30);
  EXPECT_EQ(cache.of(10).size(), 10000u);
  EXPECT_EQ(cache.of(20).size(), 20000u);
  EXPECT_EQ(cache.of(10).size(), 10000u);
  EXPECT_EQ(loads.years, (std::vector<int>{10, 20}));
  EXPECT_EQ(cache.keptCount(), 2u);
  EXPECT_EQ(cache.keptBytes(), forestOfSize(30000).memoryBytes());
}

TEST(ForestCache, TheLeastRecentlyShownGoFirstAndRoomIsMadeBeforeAYearIsRead) {
  // Forests of one size, and room for two and a half of them.
  const std::uint64_t one = forestOfSize(10000).memoryBytes();
  std::vector<int> loads;
  std::vector<std::uint64_t> keptWhileReading;
  ForestCache* cache = nullptr;
  ForestCache forests(
      [&](int year) {
        loads.push_back(year);
        keptWhileReading.push_back(cache->keptBytes());
        return forestOfSize(10000);
      },
      2 * one + one / 2);
  cache = &forests;
  forests.of(1);
  forests.of(2);
  forests.of(1);  // 2 is now the least recently shown
  forests.of(3);  // and goes before 3 is read
  EXPECT_EQ(loads, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(keptWhileReading, (std::vector<std::uint64_t>{0, one, one}));
  EXPECT_EQ(forests.keptCount(), 2u);
  forests.of(1);
  EXPECT_EQ(loads.size(), 3u);  // 1 was kept
  forests.of(2);
  EXPECT_EQ(loads.back(), 2);  // 2 was not
  EXPECT_LE(forests.keptBytes(), 2 * one + one / 2);
}

TEST(ForestCache, AForestLargerThanTheBudgetIsShownAndKeptAlone) {
  CountedLoads loads;
  ForestCache cache(loads.load(), forestOfSize(15000).memoryBytes());
  cache.of(10);
  EXPECT_EQ(cache.of(40).size(), 40000u);
  EXPECT_EQ(cache.keptCount(), 1u);
  EXPECT_EQ(cache.of(40).size(), 40000u);
  EXPECT_EQ(loads.years, (std::vector<int>{10, 40}));
}

}  // namespace
}  // namespace eco
