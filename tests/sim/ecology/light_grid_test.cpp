#include "sim/ecology/light_grid.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/random.hpp"

namespace eco {
namespace {

// A flat 50 m x 50 m map of 5 m cells: 10 x 10 light columns, cell centres at 0, 5, ...
// so column (x, y) spans east [-2.5 + 5x, 2.5 + 5x).
struct FiftyMetres {
  Grid grid{10, 10, 5.0, 5.0};
  LightGrid light{grid, Field(grid.cellCount(), 1.0f)};
};

double discArea(double r) {
  return std::numbers::pi * r * r;
}

TEST(LightGrid, ACrownAloneAbsorbsByBeersLaw) {
  FiftyMetres m;
  const CrownShape crown{20.0f, 20.0f, 2.0f, 15.0f, 30.0f};
  m.light.compute({crown});
  const double expected = discArea(2.0) * (1.0 - std::exp(-kLeafExtinction * 30.0 / discArea(2.0)));
  EXPECT_NEAR(m.light.absorbed(0), expected, 1e-4);
  EXPECT_NEAR(LightGrid::absorbedInTheOpen(crown), expected, 1e-4);
  // A wide crown shared over several columns absorbs as much as alone in the open.
  const CrownShape wide{22.0f, 21.0f, 6.0f, 20.0f, 200.0f};
  m.light.compute({wide});
  EXPECT_NEAR(m.light.absorbed(0), LightGrid::absorbedInTheOpen(wide),
              1e-4 * LightGrid::absorbedInTheOpen(wide));
}

TEST(LightGrid, TheTallerCrownTakesItsLightFirst) {
  FiftyMetres m;
  const CrownShape tall{20.0f, 20.0f, 2.0f, 20.0f, 30.0f}, low{21.0f, 21.0f, 2.0f, 10.0f, 30.0f};
  m.light.compute({low, tall});
  const double share = 1.0 - std::exp(-kLeafExtinction * 30.0 / discArea(2.0));
  const double takenByTall = discArea(2.0) * share;
  EXPECT_NEAR(m.light.absorbed(1), takenByTall, 1e-4);
  const double leftInColumn = 1.0 - takenByTall / (kLightColumn_m * kLightColumn_m);
  EXPECT_NEAR(m.light.absorbed(0), discArea(2.0) * leftInColumn * share, 1e-4);
  // The light profile of the column: open above, then what each crown leaves.
  EXPECT_DOUBLE_EQ(m.light.lightAt(20.0, 20.0, 25.0), 1.0);
  EXPECT_NEAR(m.light.lightAt(20.0, 20.0, 15.0), leftInColumn, 1e-6);
  EXPECT_NEAR(m.light.lightAt(20.0, 20.0, 1.0),
              leftInColumn - m.light.absorbed(0) / (kLightColumn_m * kLightColumn_m), 1e-6);
  EXPECT_DOUBLE_EQ(m.light.groundLightAt(20.0, 20.0), m.light.lightAt(20.0, 20.0, 0.0));
  // The same asked of the column, and the column of its two parts.
  const long column = m.light.columnAt(20.0, 20.0);
  EXPECT_EQ(column, m.light.columnYAt(20.0) * m.light.columnsX() + m.light.columnXAt(20.0));
  EXPECT_EQ(m.light.columnXAt(20.0), 4);
  EXPECT_EQ(m.light.columnYAt(-30.0), 0);  // clamped to the map
  EXPECT_EQ(m.light.groundLightInColumn(column), m.light.groundLightAt(20.0, 20.0));
  EXPECT_DOUBLE_EQ(m.light.skyLightInColumn(column), 1.0);
  // The neighbouring column is untouched.
  EXPECT_DOUBLE_EQ(m.light.lightAt(30.0, 20.0, 1.0), 1.0);
  // Crown pruning: the lowest height with at least this much light beside a crown, the
  // mean of four columns. A stem 5 m east of these crowns has three open columns beside it
  // and theirs to the west.
  const double bottom = m.light.lightAt(20.0, 20.0, 1.0);
  auto side = [&](double light) {
    return m.light.heightWithSideLight(25.0, 20.0, 5.0, 0.0, 30.0, light);
  };
  EXPECT_DOUBLE_EQ(side((3.0 + bottom) / 4.0 - 0.001), 0.0);
  EXPECT_DOUBLE_EQ(side((3.0 + leftInColumn) / 4.0 - 0.001), 10.0);
  EXPECT_DOUBLE_EQ(side((3.0 + leftInColumn) / 4.0 + 0.001), 20.0);
  EXPECT_DOUBLE_EQ(side(1.01), 30.0);
  // The crowns over a stem's own column do not prune it: its sides are open.
  EXPECT_DOUBLE_EQ(m.light.heightWithSideLight(20.0, 20.0, 5.0, 0.0, 30.0, 0.99), 0.0);
  // Pruning never goes back down: the search starts at the crown base it is given.
  EXPECT_DOUBLE_EQ(m.light.heightWithSideLight(25.0, 20.0, 5.0, 12.0, 30.0, 0.01), 12.0);
  EXPECT_DOUBLE_EQ(LightGrid::beyondCrown_m(2.0), 2.0 + kLightColumn_m * std::numbers::sqrt2);
}

// The side light's definition, evaluated the slow way through lightAt: the lowest of
// `from` and the crown tops above it, below `top`, where the mean light of the four columns
// beside the stem suffices.
double sideLightHeightByDefinition(const LightGrid& light, const std::vector<CrownShape>& crowns,
                                   double east, double north, double reach, double from, double top,
                                   double wanted) {
  auto sideLight = [&](double height) {
    return 0.25 * (light.lightAt(east + reach, north, height) +
                   light.lightAt(east, north + reach, height) +
                   light.lightAt(east - reach, north, height) +
                   light.lightAt(east, north - reach, height));
  };
  std::vector<double> heights{from};
  for (const CrownShape& crown : crowns)
    if (crown.top_m > from && crown.top_m < top) heights.push_back(crown.top_m);
  std::sort(heights.begin(), heights.end());
  for (double height : heights)
    if (sideLight(height) >= wanted) return height;
  return top;
}

TEST(LightGrid, OfCrownsOfOneHeightTheEarlierTakesItsLightFirst) {
  FiftyMetres m;
  // Two crowns of one column and one height, and a wide one of the same height over them.
  const CrownShape a{20.0f, 20.0f, 2.0f, 12.0f, 30.0f}, b{21.0f, 21.0f, 1.5f, 12.0f, 20.0f};
  const CrownShape wide{21.0f, 19.0f, 6.0f, 12.0f, 150.0f};
  const double shareA = 1.0 - std::exp(-kLeafExtinction * 30.0 / discArea(2.0));
  m.light.compute({a, b});
  EXPECT_NEAR(m.light.absorbed(0), discArea(2.0) * shareA, 1e-4);  // in the open sky's light
  const double firstB = m.light.absorbed(1);
  m.light.compute({b, a});
  EXPECT_NEAR(m.light.absorbed(0), LightGrid::absorbedInTheOpen(b), 1e-4);
  EXPECT_LT(m.light.absorbed(1), discArea(2.0) * shareA - 1e-3);  // under b now
  EXPECT_GT(m.light.absorbed(0), firstB + 1e-3);
  // The wide crown covers other columns: in theirs it is first, in the shared one last.
  m.light.compute({a, b, wide});
  const double lastWide = m.light.absorbed(2);
  EXPECT_LT(lastWide, LightGrid::absorbedInTheOpen(wide));
  m.light.compute({wide, a, b});
  EXPECT_NEAR(m.light.absorbed(0), LightGrid::absorbedInTheOpen(wide),
              1e-4 * LightGrid::absorbedInTheOpen(wide));
  EXPECT_GT(m.light.absorbed(0), lastWide);
}

TEST(LightGrid, TheSideLightHeightIsTheLowestTopWhereTheLightSuffices) {
  // A dense, uneven canopy of 400 crowns: every stem's answer for a range of thresholds
  // and starting heights, against the definition.
  FiftyMetres m;
  Rng rng(7);
  std::vector<CrownShape> crowns;
  for (int i = 0; i < 400; ++i)
    crowns.push_back({static_cast<float>(50.0 * rng.uniform() - 2.5),
                      static_cast<float>(50.0 * rng.uniform() - 2.5),
                      static_cast<float>(0.3 + 4.0 * rng.uniform()),
                      static_cast<float>(1.3 + 30.0 * rng.uniform()),
                      static_cast<float>(80.0 * rng.uniform())});
  m.light.compute(crowns);
  int checked = 0, insideTheCrown = 0;
  for (std::size_t i = 0; i < crowns.size(); i += 7) {
    const CrownShape& c = crowns[i];
    const double reach = LightGrid::beyondCrown_m(c.radius_m);
    for (double from : {0.0, 0.3 * c.top_m, 0.7 * c.top_m})
      for (double wanted : {0.02, 0.1, 0.3, 0.6, 0.9}) {
        const double height =
            m.light.heightWithSideLight(c.east_m, c.north_m, reach, from, c.top_m, wanted);
        EXPECT_EQ(height, sideLightHeightByDefinition(m.light, crowns, c.east_m, c.north_m, reach,
                                                      from, c.top_m, wanted))
            << "crown " << i << ", from " << from << ", light " << wanted;
        ++checked;
        insideTheCrown += height > from && height < c.top_m;
      }
  }
  EXPECT_EQ(checked, 58 * 15);
  // The canopy is dense enough that many answers lie between the two ends (139 of 870).
  EXPECT_GT(insideTheCrown, checked / 10);
}

TEST(LightGrid, AColumnNeverGivesMoreLightThanReachesIt) {
  FiftyMetres m;
  std::vector<CrownShape> crowns;
  for (int i = 0; i < 40; ++i)
    crowns.push_back({20.0f + 0.05f * i, 20.0f, 2.4f, 5.0f + 0.5f * i, 60.0f});
  m.light.compute(crowns);
  double total = 0.0;
  for (std::size_t i = 0; i < crowns.size(); ++i) total += m.light.absorbed(i);
  EXPECT_LE(total, kLightColumn_m * kLightColumn_m * 1.000001);
  EXPECT_GT(total, 0.99 * kLightColumn_m * kLightColumn_m);  // 40 thick crowns take nearly all
  // Deep in the stack a crown gets almost nothing.
  EXPECT_LT(m.light.absorbed(0), 1e-3 * m.light.absorbed(39));
}

TEST(LightGrid, TheTerrainsLightScalesWhatCrownsGet) {
  Grid grid{10, 10, 5.0, 5.0};
  LightGrid half(grid, Field(grid.cellCount(), 0.5f));
  const CrownShape crown{20.0f, 20.0f, 2.0f, 15.0f, 30.0f};
  half.compute({crown});
  EXPECT_NEAR(half.absorbed(0), 0.5 * LightGrid::absorbedInTheOpen(crown), 1e-4);
  EXPECT_DOUBLE_EQ(half.lightAt(20.0, 20.0, 30.0), 0.5);
}

TEST(LightGrid, ARowWithoutLeavesIsNoCrown) {
  // The ecosystem gives the grid a row for every plant, and one below breast height has no
  // leaves: it takes no light, shades nothing and leaves no layer in its column.
  FiftyMetres m;
  const CrownShape leafless{20.0f, 20.0f, 2.0f, 20.0f, 0.0f};
  const CrownShape low{21.0f, 21.0f, 2.0f, 10.0f, 30.0f};
  m.light.compute({leafless, low});
  EXPECT_EQ(m.light.absorbed(0), 0.0);
  EXPECT_DOUBLE_EQ(m.light.absorbed(1), LightGrid::absorbedInTheOpen(low));
  EXPECT_DOUBLE_EQ(m.light.lightAt(20.0, 20.0, 15.0), 1.0);
}

TEST(LightGrid, CrownColumnsDrawNoCrownNarrowerThanTheLeast) {
  FiftyMetres m;
  const std::vector<float> east{20.0f, 40.0f}, north{20.0f, 40.0f}, radius{0.01f, 1.5f},
      top{5.0f, 8.0f}, leafArea{0.002f, 6.0f};
  const std::vector<std::uint32_t> rows{0, 1};
  m.light.compute(CrownColumns{east, north, radius, top, rows, leafArea});
  EXPECT_DOUBLE_EQ(m.light.absorbed(0),
                   LightGrid::absorbedInTheOpen({20.0f, 20.0f, kMinCrownRadius_m, 5.0f, 0.002f}));
  EXPECT_DOUBLE_EQ(m.light.absorbed(1),
                   LightGrid::absorbedInTheOpen({40.0f, 40.0f, 1.5f, 8.0f, 6.0f}));
}

// The crowns are the rows listed, in their order, each with its own leaf area: a row not
// listed (a sapling) takes no light and casts no shade, however tall.
TEST(LightGrid, CrownColumnsAreTheListedRowsOnly) {
  FiftyMetres m;
  const std::vector<float> east{20.0f, 20.5f, 40.0f}, north{20.0f, 20.5f, 40.0f},
      radius{1.5f, 2.0f, 1.5f}, top{8.0f, 30.0f, 6.0f}, leafArea{6.0f, 4.0f};
  const std::vector<std::uint32_t> rows{0, 2};
  m.light.compute(CrownColumns{east, north, radius, top, rows, leafArea});
  EXPECT_DOUBLE_EQ(m.light.absorbed(0),
                   LightGrid::absorbedInTheOpen({20.0f, 20.0f, 1.5f, 8.0f, 6.0f}));
  EXPECT_DOUBLE_EQ(m.light.absorbed(1),
                   LightGrid::absorbedInTheOpen({40.0f, 40.0f, 1.5f, 6.0f, 4.0f}));
  EXPECT_DOUBLE_EQ(m.light.lightAt(20.0, 20.0, 10.0), 1.0);  // row 1's 30 m top shades nothing
  EXPECT_LT(m.light.lightAt(20.0, 20.0, 0.0), 1.0);
  // Crown 1 is row 2, 6 m tall (row 1's 30 m height is not its).
  EXPECT_DOUBLE_EQ(m.light.lightAt(40.0, 40.0, 7.0), 1.0);
  EXPECT_LT(m.light.lightAt(40.0, 40.0, 5.0), 1.0);
}

TEST(LightGrid, TheOrderOfTheCrownsAndTheThreadCountDoNotMatter) {
  FiftyMetres m;
  std::vector<CrownShape> crowns;
  for (int i = 0; i < 300; ++i)
    crowns.push_back({static_cast<float>((i * 37) % 47), static_cast<float>((i * 53) % 43),
                      1.0f + static_cast<float>(i % 7),
                      3.0f + static_cast<float>((i * 11) % 29) + 0.001f * static_cast<float>(i),
                      20.0f + static_cast<float>(i % 13) * 10.0f});
  std::vector<double> forward;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    m.light.compute(crowns);
    for (std::size_t i = 0; i < crowns.size(); ++i) forward.push_back(m.light.absorbed(i));
  }
  std::vector<CrownShape> reversed(crowns.rbegin(), crowns.rend());
  m.light.compute(reversed);
  // Every height is different (ties would go to the earlier crown), so each crown takes the
  // same light in either order.
  for (std::size_t i = 0; i < crowns.size(); ++i)
    EXPECT_NEAR(m.light.absorbed(crowns.size() - 1 - i), forward[i], 1e-9 + 1e-9 * forward[i]);
  m.light.compute(crowns);
  for (std::size_t i = 0; i < crowns.size(); ++i) EXPECT_EQ(m.light.absorbed(i), forward[i]);
}

TEST(LightGrid, AGridUsedYearAfterYearAnswersAsAFreshOne) {
  // compute() keeps its working arrays from one call to the next: whatever a year with more
  // or fewer crowns left in them must not reach the next year's light.
  auto canopy = [](int count, int seed) {
    std::vector<CrownShape> crowns;
    Rng rng(static_cast<std::uint64_t>(seed));
    for (int i = 0; i < count; ++i)
      crowns.push_back({static_cast<float>(47.0 * rng.uniform()),
                        static_cast<float>(47.0 * rng.uniform()),
                        static_cast<float>(0.3 + 6.0 * rng.uniform()),
                        static_cast<float>(1.5 + 25.0 * rng.uniform()),
                        static_cast<float>(200.0 * rng.uniform())});
    return crowns;
  };
  FiftyMetres used;
  for (const auto& [count, seed] : {std::pair{400, 1}, std::pair{25, 2}, std::pair{900, 3}}) {
    const std::vector<CrownShape> crowns = canopy(count, seed);
    used.light.compute(crowns);
    FiftyMetres fresh;
    fresh.light.compute(crowns);
    for (std::size_t i = 0; i < crowns.size(); ++i)
      ASSERT_EQ(used.light.absorbed(i), fresh.light.absorbed(i)) << "crown " << i;
    for (double east = 0.0; east < 50.0; east += 3.7)
      for (double north = 0.0; north < 50.0; north += 4.1) {
        ASSERT_EQ(used.light.groundLightAt(east, north), fresh.light.groundLightAt(east, north));
        for (double height : {0.5, 4.0, 12.0, 30.0})
          ASSERT_EQ(used.light.lightAt(east, north, height),
                    fresh.light.lightAt(east, north, height));
        ASSERT_EQ(used.light.heightWithSideLight(east, north, 5.0, 1.0, 20.0, 0.3),
                  fresh.light.heightWithSideLight(east, north, 5.0, 1.0, 20.0, 0.3));
      }
  }
}

}  // namespace
}  // namespace eco
