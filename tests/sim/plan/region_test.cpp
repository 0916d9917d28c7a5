#include "sim/plan/region.hpp"

#include <gtest/gtest.h>

#include "sim/image_io.hpp"
#include "terrain_support.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

// 50 x 40 cells of 2 m: east -1 .. 99 m, north -1 .. 79 m.
const Grid kGrid{50, 40, 2.0, 2.0};

RegionSpec polygon(std::vector<glm::dvec2> corners, double buffer_m = 0.0) {
  RegionSpec spec;
  spec.kind = RegionSpec::Kind::Polygon;
  spec.points = std::move(corners);
  spec.buffer_m = buffer_m;
  spec.where = {"plan.toml", 7, "planting[0].polygon"};
  return spec;
}

TEST(Region, PolygonsHoldTheirInsideByTheEvenOddRule) {
  // An L: the notch at the north-east is outside.
  const Region l(polygon({{0, 0}, {60, 0}, {60, 30}, {30, 30}, {30, 60}, {0, 60}}), kGrid);
  EXPECT_TRUE(l.contains({10, 10}));
  EXPECT_TRUE(l.contains({10, 50}));
  EXPECT_TRUE(l.contains({50, 20}));
  EXPECT_FALSE(l.contains({50, 50}));
  EXPECT_FALSE(l.contains({70, 10}));
  // A buffer widens it by its distance, corners rounded.
  const Region wide(polygon({{0, 0}, {60, 0}, {60, 30}, {30, 30}, {30, 60}, {0, 60}}, 5.0), kGrid);
  EXPECT_TRUE(wide.contains({64.9, 10}));
  EXPECT_FALSE(wide.contains({65.1, 10}));
  EXPECT_TRUE(wide.contains({63, 33}));   // 4.2 m from the corner (60, 30)
  EXPECT_FALSE(wide.contains({64, 34}));  // 5.7 m from it
}

TEST(Region, ALineWithABufferIsAStrip) {
  RegionSpec road;
  road.kind = RegionSpec::Kind::Line;
  road.points = {{0, 40}, {98, 40}};
  road.buffer_m = 3.0;
  const Region r(road, kGrid);
  EXPECT_TRUE(r.contains({50, 42.9}));
  EXPECT_FALSE(r.contains({50, 43.1}));
  EXPECT_TRUE(r.contains({50, 37.1}));
}

TEST(Region, TheWholeMapAndABorderAroundIt) {
  const Region map(RegionSpec{}, kGrid);
  EXPECT_TRUE(map.contains({-0.9, -0.9}));
  EXPECT_FALSE(map.contains({-1.1, 10}));
  RegionSpec border;
  border.kind = RegionSpec::Kind::Border;
  border.border_m = 100.0;
  const Region around(border, kGrid, true);
  EXPECT_FALSE(around.contains({50, 40}));    // on the map
  EXPECT_TRUE(around.contains({-50, 40}));    // 49 m west of it
  EXPECT_TRUE(around.contains({-60, -60}));   // 83 m off its south-west corner
  EXPECT_FALSE(around.contains({-80, -80}));  // 111 m off it
  EXPECT_FALSE(around.contains({250, 40}));   // 151 m east
}

TEST(Region, AShapeOffTheMapIsAnErrorExceptForASeedSource) {
  const RegionSpec far = polygon({{200, 0}, {300, 0}, {300, 50}});
  try {
    Region r(far, kGrid);
    FAIL() << "a polygon off the map was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 7);
    EXPECT_NE(std::string(e.what()).find("lies outside the map, which spans east -1.0 .. 99.0 m"),
              std::string::npos);
  }
  const Region source(far, kGrid, true);
  EXPECT_TRUE(source.contains({250, 10}));
}

TEST(Region, AMaskMustHaveTheTerrainsSizeAndCanBeWidened) {
  const auto folder = test::freshDirectory("region_mask");
  std::vector<float> white(kGrid.cellCount(), 0.0f);
  white[kGrid.index(10, 10)] = 1.0f;  // one cell: east 20 m, north 58 m
  writeFloatImage(folder / "mask.exr", kGrid.width, kGrid.height, 1, white);
  RegionSpec mask;
  mask.kind = RegionSpec::Kind::Mask;
  mask.mask = folder / "mask.exr";
  mask.where = {"plan.toml", 3, "exclusion[0].mask"};
  const Region one(mask, kGrid);
  EXPECT_TRUE(one.contains({20, 58}));
  EXPECT_FALSE(one.contains({22, 58}));
  mask.buffer_m = 2.0;
  const Region wider(mask, kGrid);
  EXPECT_TRUE(wider.contains({22, 58}));
  EXPECT_FALSE(wider.contains({22, 60}));  // the diagonal neighbour is 2.8 m away
  writeFloatImage(folder / "small.exr", 10, 10, 1, std::vector<float>(100, 1.0f));
  mask.mask = folder / "small.exr";
  try {
    Region r(mask, kGrid);
    FAIL() << "a mask of the wrong size was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 3);
    EXPECT_NE(std::string(e.what()).find("is 10 x 10 pixels; the terrain is 50 x 40 cells"),
              std::string::npos);
  }
}

TEST(Region, ItsAreaCountsTheLandscapeCellsInside) {
  const Terrain terrain =
      test::analyticTerrain(50, 40, 2.0, 2.0, [](double, double) { return 0.0; });
  const Region square(polygon({{-1, -1}, {19, -1}, {19, 19}, {-1, 19}}), terrain.grid);
  EXPECT_DOUBLE_EQ(square.areaOnLandscape_m2(terrain), 400.0);  // 10 x 10 cells of 4 m2
}

}  // namespace
}  // namespace eco
