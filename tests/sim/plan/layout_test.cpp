#include "sim/plan/layout.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "terrain_support.hpp"

namespace eco {
namespace {

Planting plantingWith(PlantingLayout layout, double spacing_m, double rowSpacing_m) {
  Planting p;
  p.layout = layout;
  p.spacing_m = spacing_m;
  p.rowSpacing_m = rowSpacing_m;
  return p;
}

double nearestNeighbour(const std::vector<PlantingSpot>& spots, std::size_t i) {
  double best = 1e300;
  for (std::size_t j = 0; j < spots.size(); ++j)
    if (j != i)
      best = std::min(best, std::hypot(spots[j].position.x - spots[i].position.x,
                                       spots[j].position.y - spots[i].position.y));
  return best;
}

// 100 m x 100 m of level ground, cells of 2 m: east and north -1 .. 99 m.
const Terrain kFlat = test::analyticTerrain(50, 50, 2.0, 2.0, [](double, double) { return 300.0; });

TEST(Layout, ASquareGridSitsOnItsLatticeFromTheSouthWestCorner) {
  const Region map(RegionSpec{}, kFlat.grid);
  const PlantingLayoutResult result =
      layoutPlanting(plantingWith(PlantingLayout::Square, 2.5, 4.0), map, kFlat, 1);
  ASSERT_EQ(result.spots.size(), 40u * 25u);  // 100 m / 2.5 m a row, 100 m / 4 m of rows
  for (const PlantingSpot& s : result.spots) {
    const double column = (s.position.x + 1.0) / 2.5 - 0.5, row = (s.position.y + 1.0) / 4.0 - 0.5;
    EXPECT_NEAR(column, std::round(column), 1e-9);
    EXPECT_NEAR(row, std::round(row), 1e-9);
    EXPECT_EQ(s.row, static_cast<int>(std::round(row)));
  }
}

TEST(Layout, ATriangularGridGivesEveryTreeSixNeighboursAtOneSpacing) {
  RegionSpec inner;
  inner.kind = RegionSpec::Kind::Polygon;
  inner.points = {{20, 20}, {80, 20}, {80, 80}, {20, 80}};
  const Region region(inner, kFlat.grid);
  const double s = 3.0;
  const std::vector<PlantingSpot> spots =
      layoutPlanting(plantingWith(PlantingLayout::Triangular, s, s * std::sqrt(3.0) / 2.0), region,
                     kFlat, 1)
          .spots;
  ASSERT_GT(spots.size(), 400u);
  int interior = 0;
  for (std::size_t i = 0; i < spots.size(); ++i) {
    const glm::dvec2 p = spots[i].position;
    EXPECT_NEAR(nearestNeighbour(spots, i), s, 1e-9);
    if (p.x < 26 || p.x > 74 || p.y < 26 || p.y > 74) continue;
    int atOneSpacing = 0;
    for (const PlantingSpot& q : spots)
      atOneSpacing += std::abs(std::hypot(q.position.x - p.x, q.position.y - p.y) - s) < 1e-9;
    EXPECT_EQ(atOneSpacing, 6);
    ++interior;
  }
  EXPECT_GT(interior, 200);
}

// On a plane rising 20 % to the north the contour lines run east-west: the rows are straight,
// exactly one row spacing apart, level, with the trees one spacing apart along them.
TEST(Layout, ContourRowsOnAPlaneAreLevelAndEvenlySpaced) {
  const Terrain slope =
      test::analyticTerrain(50, 50, 2.0, 2.0, [](double, double north) { return 0.2 * north; });
  const Region map(RegionSpec{}, slope.grid);
  EXPECT_NEAR(meanGradient(slope, map), 0.2, 1e-5);
  const PlantingLayoutResult result =
      layoutPlanting(plantingWith(PlantingLayout::Contour, 3.0, 4.0), map, slope, 1);
  EXPECT_TRUE(result.note.empty());
  std::map<int, std::vector<glm::dvec2>> rows;
  for (const PlantingSpot& s : result.spots) rows[s.row].push_back(s.position);
  ASSERT_GE(rows.size(), 23u);
  double previousNorth = -1e9;
  for (auto& [row, trees] : rows) {
    std::sort(trees.begin(), trees.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x; });
    for (const glm::dvec2& t : trees) EXPECT_NEAR(t.y, trees.front().y, 1e-3);
    for (std::size_t k = 1; k < trees.size(); ++k)
      EXPECT_NEAR(trees[k].x - trees[k - 1].x, 3.0, 1e-6);
    if (previousNorth > -1e9) {
      EXPECT_NEAR(trees.front().y - previousNorth, 4.0, 2e-3);
    }
    previousNorth = trees.front().y;
  }
}

// Around a round hill the rows are circles: trees lie on them one spacing apart.
TEST(Layout, ContourRowsFollowARoundHill) {
  const Terrain hill = test::analyticTerrain(50, 50, 2.0, 2.0, [](double east, double north) {
    return 100.0 - 0.5 * std::hypot(east - 49.0, north - 49.0);
  });
  const Region map(RegionSpec{}, hill.grid);
  const std::vector<PlantingSpot> spots =
      layoutPlanting(plantingWith(PlantingLayout::Contour, 2.0, 5.0), map, hill, 1).spots;
  std::map<int, std::vector<double>> radii;
  for (const PlantingSpot& s : spots)
    radii[s.row].push_back(std::hypot(s.position.x - 49.0, s.position.y - 49.0));
  int circles = 0;
  for (const auto& [row, r] : radii) {
    const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
    if (*hi > 45.0 || *lo < 6.0) continue;  // cut by the map's edge, or the top's sharp cone
    EXPECT_LT(*hi - *lo, 0.1) << "row " << row;
    // A circle of circumference 2 pi r holds about 2 pi r / 2 trees.
    EXPECT_NEAR(static_cast<double>(r.size()), 2.0 * 3.14159265 * *lo / 2.0, 1.5) << "row " << row;
    ++circles;
  }
  EXPECT_GE(circles, 6);
  for (std::size_t i = 0; i < spots.size(); ++i) EXPECT_GT(nearestNeighbour(spots, i), 1.9);
}

TEST(Layout, ContourRowsOnLevelGroundFallBackToRowsAndSaySo) {
  const Region map(RegionSpec{}, kFlat.grid);
  const PlantingLayoutResult result =
      layoutPlanting(plantingWith(PlantingLayout::Contour, 2.0, 2.0), map, kFlat, 1);
  EXPECT_NE(result.note.find("flatter than 1 %"), std::string::npos);
  EXPECT_EQ(result.spots.size(), 2500u);
}

TEST(Layout, RandomSpotsKeepTheirMinimumDistanceAndTheDensity) {
  const Region map(RegionSpec{}, kFlat.grid);
  Planting random = plantingWith(PlantingLayout::Random, 2.0, 2.0);
  random.minDistance_m = 1.5;
  const std::vector<PlantingSpot> spots = layoutPlanting(random, map, kFlat, 9).spots;
  EXPECT_EQ(spots.size(), 2500u);  // 1 ha at one tree per 4 m2
  for (std::size_t i = 0; i < spots.size(); ++i) EXPECT_GE(nearestNeighbour(spots, i), 1.5);
  const std::vector<PlantingSpot> again = layoutPlanting(random, map, kFlat, 9).spots;
  ASSERT_EQ(again.size(), spots.size());
  for (std::size_t i = 0; i < spots.size(); ++i) EXPECT_EQ(again[i].position, spots[i].position);
  EXPECT_NE(layoutPlanting(random, map, kFlat, 10).spots[0].position, spots[0].position);
}

}  // namespace
}  // namespace eco
