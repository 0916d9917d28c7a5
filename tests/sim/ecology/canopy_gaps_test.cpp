#include "sim/ecology/canopy_gaps.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "terrain_support.hpp"

namespace eco {
namespace {

// A flat 205 m square: 41 x 41 cells of 5 m, whose centres are the gap map's cell centres.
Terrain flatSquare() {
  return test::analyticTerrain(41, 41, kGapCell_m, kGapCell_m,
                               [](double, double) { return 300.0; });
}

void addPlant(Plants& p, int species, double east, double north, float height, float crownRadius) {
  const std::size_t i = p.size();
  p.resize(i + 1);
  p.id[i] = i + 1;
  p.species[i] = static_cast<std::uint8_t>(species);
  p.east_m[i] = static_cast<float>(east), p.north_m[i] = static_cast<float>(north);
  p.height_m[i] = height;
  p.crownRadius_m[i] = crownRadius;
  p.alive[i] = 1;
}

// Trees of species 1, `height` tall, one on each cell centre, their crowns of 3 m covering
// every sample point of their cell; none within `holeRadius` of the map's middle.
constexpr double kMiddle = 100.0;
Plants canopyWithHole(float height, double holeRadius) {
  Plants p;
  for (int y = 0; y < 41; ++y)
    for (int x = 0; x < 41; ++x)
      if (std::hypot(5.0 * x - kMiddle, 5.0 * y - kMiddle) > holeRadius)
        addPlant(p, 1, 5.0 * x, 5.0 * y, height, 3.0f);
  return p;
}

// The share of the map's cell centres within `radius` of the middle.
double shareWithin(double radius) {
  int inside = 0;
  for (int y = 0; y < 41; ++y)
    for (int x = 0; x < 41; ++x)
      inside += std::hypot(5.0 * x - kMiddle, 5.0 * y - kMiddle) <= radius;
  return inside / (41.0 * 41.0);
}

TEST(CanopyGaps, AHoleInTheCanopyIsAGapRingedByItsEdge) {
  const CanopyGapMap gaps(canopyWithHole(25.0f, 25.0), flatSquare());
  EXPECT_EQ(gaps.at(kMiddle, kMiddle), CanopyPlace::Gap);
  EXPECT_EQ(gaps.at(kMiddle, kMiddle + 20.0), CanopyPlace::Gap);
  // Along the axes the gap ends 20 m out (the hole's cell at 25 m has more than half of its
  // neighbourhood covered); the edge reaches 10 m beyond, and the canopy is closed from 35 m.
  EXPECT_EQ(gaps.at(kMiddle, kMiddle + 30.0), CanopyPlace::Edge);
  EXPECT_EQ(gaps.at(kMiddle - 30.0, kMiddle), CanopyPlace::Edge);
  EXPECT_EQ(gaps.at(kMiddle + 35.0, kMiddle), CanopyPlace::Closed);
  EXPECT_EQ(gaps.at(kMiddle - 40.0, kMiddle), CanopyPlace::Closed);
  EXPECT_EQ(gaps.at(10.0, 10.0), CanopyPlace::Closed);
  EXPECT_EQ(gaps.at(-10.0, 10.0), CanopyPlace::Outside);  // off the map
  // The map's shares: about the hole's cells, then those within 10 m more.
  const CanopyGapShares shares = gaps.shares();
  EXPECT_NEAR(shares.gaps, shareWithin(25.0), 0.1 * shareWithin(25.0));
  EXPECT_NEAR(shares.gapsOrEdges, shareWithin(35.0), 0.1 * shareWithin(35.0));
}

TEST(CanopyGaps, TreesBelowTheCanopyHeightLeaveTheGroundOpen) {
  const CanopyGapMap low(canopyWithHole(static_cast<float>(kCanopyTreeHeight_m) - 0.5f, 25.0),
                         flatSquare());
  EXPECT_DOUBLE_EQ(low.shares().gaps, 1.0);
  const CanopyGapMap closed(canopyWithHole(static_cast<float>(kCanopyTreeHeight_m), 0.0),
                            flatSquare());
  EXPECT_DOUBLE_EQ(closed.shares().gapsOrEdges, 0.0);
}

TEST(CanopyGaps, CountsEachSpeciesStemsWhereTheyStand) {
  Plants p = canopyWithHole(25.0f, 25.0);
  addPlant(p, 0, kMiddle + 2.0, kMiddle - 1.0, 3.0f, 0.8f);   // in the gap
  addPlant(p, 0, kMiddle + 1.0, kMiddle + 30.0, 4.0f, 0.8f);  // at its edge
  addPlant(p, 0, 12.0, 11.0, 2.0f, 0.6f);                     // under the closed canopy
  addPlant(p, 0, kMiddle, kMiddle, 0.5f, 0.2f);               // a seedling: not a stem
  const CanopyGapMap gaps(p, flatSquare());
  const std::vector<GapStems> stems = gapStemsOf(p, gaps, 3);
  ASSERT_EQ(stems.size(), 3u);
  EXPECT_EQ(stems[0].stems, 3);
  EXPECT_DOUBLE_EQ(stems[0].shares.gaps, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(stems[0].shares.gapsOrEdges, 2.0 / 3.0);
  // The canopy trees stand around the hole, none in it.
  EXPECT_EQ(stems[1].stems, static_cast<std::int64_t>(p.size()) - 4);
  EXPECT_LT(stems[1].shares.gaps, 0.02);
  EXPECT_GT(stems[1].shares.gapsOrEdges, 0.0);
  EXPECT_EQ(stems[2].stems, 0);  // a species without stems has no shares
  EXPECT_DOUBLE_EQ(stems[2].shares.gapsOrEdges, 0.0);
}

TEST(CanopyGaps, CellsOffTheLandscapeCountNowhere) {
  Terrain terrain = flatSquare();
  terrain.outside.assign(terrain.grid.cellCount(), 0);
  for (int y = 0; y < 41; ++y)
    for (int x = 0; x < 20; ++x) terrain.outside[terrain.grid.index(x, y)] = 1;  // the west
  // A canopy in the east only: the landscape is closed but for its western edge.
  Plants p;
  for (int y = 0; y < 41; ++y)
    for (int x = 20; x < 41; ++x) addPlant(p, 0, 5.0 * x, 5.0 * y, 25.0f, 3.0f);
  const CanopyGapMap gaps(p, terrain);
  EXPECT_EQ(gaps.at(50.0, 100.0), CanopyPlace::Outside);
  EXPECT_EQ(gaps.at(150.0, 100.0), CanopyPlace::Closed);
  // The no-data cells beside it do not open the canopy's border into a gap.
  EXPECT_DOUBLE_EQ(gaps.shares().gapsOrEdges, 0.0);
}

}  // namespace
}  // namespace eco
