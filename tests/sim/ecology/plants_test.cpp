#include "sim/ecology/plants.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "core/random.hpp"

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
  EXPECT_EQ(columns, 15u);
}

TEST(Plants, AppendRowCopiesEveryColumn) {
  Plants from;
  from.resize(3);
  from.id = {4, 5, 6};
  from.dbh_m = {0.1f, 0.2f, 0.3f};
  from.origin = {0, 1, 2};
  Plants to;
  to.appendRow(from, 1);
  to.appendRow(from, 2);
  EXPECT_EQ(to.size(), 2u);
  to.forEachColumn([](const auto& column) { EXPECT_EQ(column.size(), 2u); });
  EXPECT_EQ(to.id, (std::vector<std::uint64_t>{5, 6}));
  EXPECT_EQ(to.dbh_m, (std::vector<float>{0.2f, 0.3f}));
  EXPECT_EQ(to.origin, (std::vector<std::uint8_t>{1, 2}));
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
  EXPECT_EQ(p.alive, (std::vector<std::uint8_t>(3, 1)));
}

TEST(Plants, RemoveDeadCompactsEveryColumnByTheSameFlags) {
  // Compacted in place, column by column, each reading the alive flags: a column compacted
  // by flags another column had already overwritten would come out shifted.
  Plants p;
  const std::size_t n = 1000;
  p.resize(n);
  std::vector<std::uint64_t> kept;
  for (std::size_t i = 0; i < n; ++i) {
    p.id[i] = i;
    p.origin[i] = static_cast<std::uint8_t>(i % 3);
    p.dbh_m[i] = static_cast<float>(i);
    p.alive[i] = (i * 7919) % 5 != 0 ? 1 : 0;
    if (p.alive[i]) kept.push_back(i);
  }
  p.removeDead();
  ASSERT_EQ(p.id, kept);
  for (std::size_t k = 0; k < kept.size(); ++k) {
    EXPECT_EQ(p.origin[k], kept[k] % 3);
    EXPECT_EQ(p.dbh_m[k], static_cast<float>(kept[k]));
  }
}

TEST(Plants, SettleTailMergesTheNewRowsStablyByKey) {
  // Rows 0-5 are in order of key (kept in east_m), rows 6-10 are not; on equal keys the
  // settled rows come first, then the new ones in their present order.
  const std::vector<int> keys{1, 2, 2, 4, 7, 9, 4, 0, 9, 2, 4};
  Plants p;
  p.resize(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    p.id[i] = 100 + i;
    p.east_m[i] = static_cast<float>(keys[i]);
    p.age_years[i] = static_cast<int>(i);
    p.stressYears[i] = static_cast<std::uint16_t>(i);
  }
  p.settleTail(6, [&](std::size_t i) { return p.east_m[i]; });
  EXPECT_EQ(p.id,
            (std::vector<std::uint64_t>{107, 100, 101, 102, 109, 103, 106, 110, 104, 105, 108}));
  // Every column moved with its row.
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto row = static_cast<std::size_t>(p.id[k] - 100);
    EXPECT_EQ(p.east_m[k], static_cast<float>(keys[row]));
    EXPECT_EQ(p.age_years[k], static_cast<int>(row));
    EXPECT_EQ(p.stressYears[k], row);
  }
  // Settled again with nothing new, or with a tail already in place, nothing moves.
  const std::vector<std::uint64_t> settled = p.id;
  p.settleTail(p.size(), [&](std::size_t i) { return p.east_m[i]; });
  p.settleTail(8, [&](std::size_t i) { return p.east_m[i]; });
  p.settleTail(0, [&](std::size_t i) { return p.east_m[i]; });
  EXPECT_EQ(p.id, settled);
}

TEST(Plants, SettleTailAgreesWithAStableSortOfEveryRow) {
  // A year's worth at a small scale: 20,000 settled rows and 9,000 new ones (the new rows'
  // places are searched for in blocks of up to 4,096, side by side), keys from a narrow range so
  // that many are equal, and new keys below and above every settled one.
  Rng rng(streamKey(17, purpose("test")));
  constexpr std::size_t kSettled = 20000, kNew = 9000;
  std::vector<int> keys(kSettled + kNew);
  for (int& key : keys) key = static_cast<int>(rng.uniform() * 500.0);
  std::sort(keys.begin(), keys.begin() + kSettled);
  keys[kSettled] = -1;
  keys[kSettled + 1] = 1000;
  Plants p;
  p.resize(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    p.id[i] = i;
    p.east_m[i] = static_cast<float>(keys[i]);
    p.dbh_m[i] = static_cast<float>(i);
  }
  // What a stable sort of every row by key gives: settled rows first on equal keys, since
  // they come first now.
  std::vector<std::uint64_t> expected(keys.size());
  std::iota(expected.begin(), expected.end(), 0);
  std::stable_sort(expected.begin(), expected.end(),
                   [&](std::uint64_t a, std::uint64_t b) { return keys[a] < keys[b]; });
  p.settleTail(kSettled, [&](std::size_t i) { return p.east_m[i]; });
  ASSERT_EQ(p.id, expected);
  for (std::size_t k = 0; k < p.size(); ++k) {
    EXPECT_EQ(p.east_m[k], static_cast<float>(keys[expected[k]]));
    EXPECT_EQ(p.dbh_m[k], static_cast<float>(expected[k]));
  }
}

}  // namespace
}  // namespace eco
