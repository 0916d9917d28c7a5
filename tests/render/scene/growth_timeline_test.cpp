#include "render/scene/growth_timeline.hpp"

#include <filesystem>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

// Year 10: trees 1 (grows) and 2 (dies). Year 20: tree 1 taller, tree 3 established in year 16.
struct Pair {
  TreeSnapshot before, after;
};

Pair pair() {
  Pair p;
  p.before.year = 10;
  p.before.speciesNames = {"maple"};
  p.before.trees = {{.id = 1,
                     .species = 0,
                     .east_m = 10,
                     .north_m = 10,
                     .ground_m = 100,
                     .age_years = 10,
                     .height_m = 4.0f,
                     .crownRadius_m = 1.0f,
                     .vigor = 0.6f,
                     .variantSeed = 1},
                    {.id = 2,
                     .species = 0,
                     .east_m = 30,
                     .north_m = 10,
                     .ground_m = 100,
                     .age_years = 30,
                     .height_m = 9.0f,
                     .crownRadius_m = 2.0f,
                     .vigor = 0.2f,
                     .variantSeed = 2}};
  p.after.year = 20;
  p.after.speciesNames = {"beech", "maple"};
  p.after.trees = {{.id = 3,
                    .species = 0,
                    .east_m = 50,
                    .north_m = 10,
                    .ground_m = 100,
                    .age_years = 4,
                    .height_m = 1.0f,
                    .crownRadius_m = 0.3f,
                    .vigor = 1.0f,
                    .variantSeed = 3},
                   {.id = 1,
                    .species = 1,
                    .east_m = 10,
                    .north_m = 10,
                    .ground_m = 100,
                    .age_years = 20,
                    .height_m = 8.0f,
                    .crownRadius_m = 2.0f,
                    .vigor = 0.8f,
                    .variantSeed = 1}};
  return p;
}

const TreeLibrary& library() {
  return test::smallLibrary();
}

float heightOf(const Forest& f, std::size_t i) {
  return f.scaleY[i] * library().type(f.type[i]).height_m;
}

TEST(GrowthTimeline, MatchesTheSnapshotsAtTheirYears) {
  const Pair p = pair();
  const Forest start = GrowthInterval(p.before, p.after, library(), "run").forestAt(10.0);
  ASSERT_EQ(start.size(), 2u);  // tree 3 has not established yet
  EXPECT_NEAR(heightOf(start, 0), 4.0f, 1e-4f);
  EXPECT_NEAR(heightOf(start, 1), 9.0f, 1e-4f);
  EXPECT_FLOAT_EQ(start.presence[1], 1.0f);
  const Forest end = GrowthInterval(p.before, p.after, library(), "run").forestAt(20.0);
  ASSERT_EQ(end.size(), 2u);  // tree 2 is gone, tree 3 is there
  EXPECT_NEAR(heightOf(end, 0), 8.0f, 1e-4f);
  EXPECT_NEAR(heightOf(end, 1), 1.0f, 1e-4f);
  EXPECT_FLOAT_EQ(end.presence[1], 1.0f);
}

TEST(GrowthTimeline, SurvivorsGrowContinuouslyTheDeadFadeAndNewTreesAppearInTheirYear) {
  const Pair p = pair();
  float previousHeight = 0.0f, previousPresence = 2.0f;
  for (double year = 10.0; year < 20.0; year += 0.25) {
    const Forest f = GrowthInterval(p.before, p.after, library(), "run").forestAt(year);
    EXPECT_GT(heightOf(f, 0), previousHeight) << year;  // tree 1 grows every step
    previousHeight = heightOf(f, 0);
    EXPECT_LT(f.presence[1], previousPresence) << year;  // tree 2 fades every step
    EXPECT_NEAR(f.presence[1], 1.0 - (year - 10.0) / 10.0, 1e-5);
    previousPresence = f.presence[1];
    EXPECT_EQ(f.size(), year < 16.0 ? 2u : 3u) << year;  // tree 3 established in year 16
  }
  const Forest appearing = GrowthInterval(p.before, p.after, library(), "run").forestAt(16.5);
  EXPECT_NEAR(appearing.presence[2], 0.5f, 1e-5f);
  EXPECT_LT(heightOf(appearing, 2), 0.5f);  // a seedling still
}

TEST(GrowthTimeline, TreesBetweenAgeClassesBlendTheTwo) {
  const Pair p = pair();
  const TreeLibrary& lib = library();
  for (double year = 10.0; year <= 20.0; year += 1.0) {
    const Forest f = GrowthInterval(p.before, p.after, lib, "run").forestAt(year);
    for (std::size_t i = 0; i < f.size(); ++i) {
      EXPECT_GE(f.blendWeight[i], 0.0f);
      EXPECT_LE(f.blendWeight[i], 1.0f);
      if (f.blendType[i] >= 0) {
        EXPECT_EQ(lib.type(f.blendType[i]).ageClass, lib.type(f.type[i]).ageClass + 1);
      }
    }
  }
}

TEST(GrowthTimeline, AnIntervalPairedOnceGivesEachFrameTheForestOfItsYear) {
  // Many trees, a third dying, a third new: the frames of one interval, made in any order,
  // are the forests made afresh for their years, tree by tree.
  Pair p;
  p.before.year = 10;
  p.after.year = 20;
  p.before.speciesNames = {"maple", "beech"};
  p.after.speciesNames = {"beech", "maple"};
  for (std::uint64_t id = 1; id <= 3000; ++id) {
    const TreeRow tree{.id = id,
                       .species = static_cast<int>(id % 2),
                       .east_m = static_cast<double>(id % 60) * 5.0,
                       .north_m = static_cast<double>(id / 60) * 5.0,
                       .ground_m = 100,
                       .age_years = static_cast<int>(id % 25),
                       .height_m = 0.5f + static_cast<float>(id % 40),
                       .crownRadius_m = 0.2f + static_cast<float>(id % 7),
                       .vigor = 0.5f,
                       .variantSeed = static_cast<std::uint32_t>(id * 7)};
    if (id % 3 != 0) p.before.trees.push_back(tree);
    if (id % 3 != 1) {
      TreeRow later = tree;
      later.species = 1 - tree.species;  // the later snapshot numbers its species otherwise
      later.height_m += 2.0f;
      p.after.trees.push_back(later);
    }
  }
  const GrowthInterval interval(p.before, p.after, library(), "run");
  for (const double year : {20.0, 10.0, 13.5, 16.0, 19.9}) {
    test::expectSameForest(interval.forestAt(year),
                           GrowthInterval(p.before, p.after, library(), "run").forestAt(year));
  }
  // At the end the dead are gone: the later snapshot's trees, each once.
  EXPECT_EQ(interval.forestAt(20.0).size(), p.after.trees.size());
}

TEST(GrowthTimeline, SnapshotsReadBatchByBatchGiveTheFramesOfTheSnapshotsReadWhole) {
  // More rows than a batch of the binary reader (2^20) in each, of every height, light and
  // crown base, a fifth dying and a sixth new, so that the batches meet among the pairs.
  const TreeLibrary& library = test::shapedLibrary();
  Pair p;
  p.before.year = 40;
  p.after.year = 50;
  p.before.speciesNames = p.after.speciesNames = {"beech"};
  const std::uint64_t n = 1400000;  // 1.17 million earlier, 1.12 million later
  std::size_t newcomers = 0;
  for (std::uint64_t id = 1; id <= n; ++id) {
    const TreeRow tree = test::variedTree(id);
    if (id % 6 != 0) p.before.trees.push_back(tree);
    if (id % 5 != 0) {
      newcomers += id % 6 == 0;
      TreeRow later = tree;
      later.height_m = std::min(later.height_m * 1.3f, 40.0f);
      later.crownBase_m = 0.5f * later.height_m;
      later.site.light = -tree.site.light;
      p.after.trees.push_back(later);
    }
  }
  const RunFolder run =
      test::runHolding("growth_interval_batches", {&p.before, &p.after}, SnapshotFormat::Binary);
  const GrowthInterval whole(p.before, p.after, library, "run");
  const GrowthInterval batched(SnapshotRows::of(run, 40), SnapshotRows::of(run, 50), library,
                               "run");
  // Each tree kept once: the earlier snapshot's, then the later one's newcomers.
  EXPECT_EQ(batched.size(), p.before.trees.size() + newcomers);
  for (const double year : {40.0, 44.5, 50.0})
    test::expectSameForest(batched.forestAt(year), whole.forestAt(year));
  // A frame made in parts of any length, one after another, is the frame made whole.
  for (const std::size_t part : {std::size_t{1000}, std::size_t{4099}})
    for (const double year : {40.0, 44.5, 50.0}) {
      Forest joined;
      for (std::size_t first = 0; first < whole.size(); first += part) {
        const Forest made = whole.forestAt(year, first, std::min(first + part, whole.size()));
        for (std::size_t i = 0; i < made.size(); ++i) joined.append(made, i);
      }
      test::expectSameForest(joined, whole.forestAt(year));
    }
}

TEST(GrowthTimeline, FromTheBareLandscapeEveryTreeIsANewcomer) {
  const Pair p = pair();
  const RunFolder run = test::runHolding("growth_interval_bare", {&p.after}, SnapshotFormat::Csv);
  const GrowthInterval interval(SnapshotRows::of(run, 0), SnapshotRows::of(run, 20), library(),
                                "run");
  EXPECT_EQ(interval.size(), 2u);
  // Tree 3 (age 4) appears in year 16, tree 1 (age 20) in year 0.
  EXPECT_EQ(interval.forestAt(0.0).size(), 1u);
  EXPECT_EQ(interval.forestAt(15.9).size(), 1u);
  EXPECT_EQ(interval.forestAt(16.0).size(), 2u);
}

TEST(GrowthTimeline, ALaterSnapshotHoldingAnEarlierTreesIdTwiceIsAnInputError) {
  Pair p = pair();
  p.after.trees.push_back(p.after.trees[1]);  // tree 1 again
  p.after.trees.back().east_m = 70;
  try {
    GrowthInterval(p.before, p.after, library(), "run");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the snapshot of year 20 holds tree id 1 twice"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace eco
