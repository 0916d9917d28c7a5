// The plants of an ecosystem as parallel arrays (DESIGN.md): one column per attribute, one
// row per plant, in an order that only the run decides, so that every pass over them is
// deterministic (the ecosystem keeps them in order of place: Ecosystem::settleNewcomers).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <ranges>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.hpp"
#include "core/fixed16.hpp"

namespace eco {

// How a plant came: from a seed, or planted (sim/plan); planted stock on ground where a
// condition rules its species out, with the planting's survival check, dies in its first year.
enum class PlantOrigin : std::uint8_t { Seeded = 0, Planted = 1, PlantedRuledOut = 2 };

struct Plants {
  std::vector<std::uint64_t> id;      // unique in a run, in order of establishment
  std::vector<std::uint8_t> species;  // index into the run's species list
  // Map position (Grid::cellAt). What follows from it and the id -- the ground's altitude,
  // the grid cell, the tree model's variant seed -- is worked out where it is needed, not
  // kept: a landscape holds 100 million plants, and every byte a plant is 100 MB.
  std::vector<float> east_m, north_m;
  std::vector<std::uint16_t> age_years;  // up to kLongestLife_years (species_ecology.hpp)
  std::vector<float> height_m;
  std::vector<float> crownRadius_m;
  // Numbers that need no float's precision, in 16 bits (core/fixed16.hpp): a plant's
  // lowest living branches, below its height (at most 150 m, species_ecology.hpp), in
  // steps of 2.4 mm; this year's vigor, 0..1; the light at its crown top, as a fraction of
  // open level ground's (a sunny slope gets more than 1); its lasting growth rate, 0.55..1.
  std::vector<Fixed16<160>> crownBase_m;
  std::vector<float> dbh_m;  // stem diameter at breast height, 0 below 1.3 m
  std::vector<Fixed16<1>> vigor;
  std::vector<Fixed16<4>> light;
  std::vector<Fixed16<1>> growthFactor;
  std::vector<std::uint8_t> stressYears;  // a sapling's poor years in a row, up to 255
  std::vector<std::uint8_t> origin;       // PlantOrigin: seeded or planted
  std::vector<std::uint8_t> alive;

  // Calls f(column) for every column, in a fixed order (resizing, compaction, checkpoints).
  template <typename F>
  void forEachColumn(F&& f) {
    visitColumns(f, *this);
  }
  template <typename F>
  void forEachColumn(F&& f) const {
    visitColumns(f, *this);
  }
  // Appends row `i` of other plants, every column.
  void appendRow(const Plants& from, std::size_t i) {
    visitColumns([i](auto& mine, const auto& theirs) { mine.push_back(theirs[i]); }, *this, from);
  }

  std::size_t size() const { return id.size(); }
  void resize(std::size_t n) {
    forEachColumn([n](auto& column) { column.resize(n); });
  }
  // Drops the rows whose alive flag is 0, keeping the order of the others.
  void removeDead();
  // The rows before `first` are in order of key(row); moves the rows from `first` on among
  // them, into the same order, each after the rows of its key already there and, among
  // themselves, in their present order (a stable merge).
  template <typename Key>
  void settleTail(std::size_t first, Key&& key);

 private:
  // Moves the rows `tail` (the rows from `first` on, in their new order) among the rows
  // before them: tail[j] goes after the place[j] first rows before `first` (place never
  // falls), so to row place[j] + j.
  void mergeTail(std::size_t first, const std::vector<std::uint32_t>& tail,
                 const std::vector<std::uint32_t>& place);
  // The first row in [from, end) whose key is greater than `k`, or `end`, where the rows of
  // [0, end) are in order of key and none before `from` has a greater key: steps of 1, 2,
  // 4, ... from `from` until one passes it, then a binary search within the last step.
  template <typename K, typename Key>
  static std::size_t gallopUpperBound(std::size_t from, std::size_t end, const K& k, Key& key);
  // Calls f with the same column of each of `p...`, column by column.
  template <typename F, typename... Self>
  static void visitColumns(F&& f, Self&... p) {
    f(p.id...), f(p.species...), f(p.east_m...), f(p.north_m...), f(p.age_years...),
        f(p.height_m...), f(p.crownRadius_m...), f(p.crownBase_m...), f(p.dbh_m...), f(p.vigor...),
        f(p.light...), f(p.growthFactor...), f(p.stressYears...), f(p.origin...), f(p.alive...);
  }
};

// Work whose results are combined in plant order (the year's trees, its fruiting trees, the
// stand's sums) is done side by side in blocks of plants, each block's part in plant order,
// and the blocks' parts taken in order: the results do not depend on the thread count.
inline constexpr std::size_t kPlantBlock = 65536;

inline std::size_t plantBlocks(std::size_t plants) {
  return (plants + kPlantBlock - 1) / kPlantBlock;
}

// Calls f(block, first, end) for each block of `plants`, side by side.
template <typename F>
void forEachPlantBlock(std::size_t plants, F&& f) {
  tbb::parallel_for(std::size_t{0}, plantBlocks(plants), [&](std::size_t block) {
    f(block, block * kPlantBlock, std::min(plants, (block + 1) * kPlantBlock));
  });
}

template <typename Key>
void Plants::settleTail(std::size_t first, Key&& key) {
  const std::size_t n = size();
  if (first >= n) return;
  ECO_ASSERT(n <= std::numeric_limits<std::uint32_t>::max(), "more plants than 32 bits index");
  std::vector<std::uint32_t> tail(n - first);
  std::iota(tail.begin(), tail.end(), static_cast<std::uint32_t>(first));
  auto byKey = [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); };
  // A tail already in order (a checkpoint read back, where the tail is every row) is
  // checked in one pass, not sorted, and without a copy of its keys.
  if (std::is_sorted(tail.begin(), tail.end(), byKey)) {
    if (first == 0 || !(key(first) < key(first - 1))) return;
  } else {
    // A year's new rows come in another order: their keys are worked out once each, side
    // by side, not twice at each of the sort's comparisons.
    std::vector<decltype(key(first))> keys(tail.size());
    tbb::parallel_for(std::size_t{0}, tail.size(), [&](std::size_t j) { keys[j] = key(tail[j]); });
    std::stable_sort(tail.begin(), tail.end(), [&](std::uint32_t a, std::uint32_t b) {
      return keys[a - first] < keys[b - first];
    });
  }
  // Where each new row goes: after the rows before the tail whose key is not greater (on
  // equal keys they come first). The new rows are in order now, so each one's place is at or
  // after the place of the one before it: they are taken in blocks of up to 4,096 side by
  // side (each place is exact wherever the blocks are cut), and each place is found by a
  // galloping search from the one before (the block's first from the start). Each new row's search
  // reads the rows near the last place, where a binary search over all the rows read a score of
  // rows scattered over gigabytes at a landscape's scale (7 % of its CPU time waited for them). A
  // pass over every row's key, on one core, had made settling a tenth of the valley's run.
  std::vector<std::uint32_t> place(tail.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tail.size(), 4096), [&](const auto& block) {
    std::size_t at = 0;  // the place of the row before
    for (std::size_t j = block.begin(); j < block.end(); ++j) {
      at = gallopUpperBound(at, first, key(tail[j]), key);
      place[j] = static_cast<std::uint32_t>(at);
    }
  });
  mergeTail(first, tail, place);
}

template <typename K, typename Key>
std::size_t Plants::gallopUpperBound(std::size_t from, std::size_t end, const K& k, Key& key) {
  std::size_t lo = from, hi = from, step = 1;  // the answer is in [lo, end]
  while (hi < end && !(k < key(hi))) {
    lo = hi + 1;
    hi = lo + step;
    step *= 2;
  }
  const auto bracket = std::views::iota(lo, std::min(hi, end));
  return lo + static_cast<std::size_t>(std::ranges::upper_bound(bracket, k, std::less<>(), key) -
                                       bracket.begin());
}

}  // namespace eco
