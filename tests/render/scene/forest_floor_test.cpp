#include "render/scene/forest_floor.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/frames.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

// A tree of the small library whose drawn crown has the given radius, standing at a map
// position on the flat test terrain.
void plant(Forest& forest, const TreeLibrary& library, double east, double north,
           float crownRadius_m) {
  const int type = library.typeIndex(0, 0, 1);
  const TreeType& t = library.type(type);
  // Height chosen so that the crown radius needs no widening (add() keeps it within limits).
  const float height = t.height_m * crownRadius_m / t.crownRadius_m;
  forest.add(library, type, glm::vec3(worldFromMap(east, north, 100.0)), height, crownRadius_m,
             1.0f, 7);
}

TEST(CanopyCover, BareGroundHasNone) {
  const Terrain terrain = test::flatTerrain(9, 10.0);
  const Field cover = canopyCover(Forest{}, test::smallLibrary(), terrain.grid);
  for (float c : cover) EXPECT_EQ(c, 0.0f);
}

TEST(CanopyCover, ACrownSmallerThanACellGoesToItsStemsCell) {
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(9, 10.0);
  Forest forest;
  plant(forest, library, 41.0, 38.0, 3.0f);  // in the cell centred at (40, 40) m
  const Field cover = canopyCover(forest, library, terrain.grid);
  const Grid& g = terrain.grid;
  const float radius = library.type(forest.type[0]).crownRadius_m * forest.scaleXZ[0];
  const double expected = 1.0 - std::exp(-std::numbers::pi * radius * radius / 100.0);
  const std::size_t cell = g.index(4, g.height - 1 - 4);
  EXPECT_NEAR(cover[cell], expected, 1e-5);
  double elsewhere = 0.0;
  for (std::size_t c = 0; c < cover.size(); ++c)
    if (c != cell) elsewhere += cover[c];
  EXPECT_EQ(elsewhere, 0.0);
}

TEST(CanopyCover, AWideCrownIsSpreadOverTheCellsItCoversAndDenserStandsCoverMore) {
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(21, 5.0);
  Forest one;
  plant(one, library, 50.0, 50.0, 9.0f);
  const Field cover = canopyCover(one, library, terrain.grid);
  ASSERT_NEAR(library.type(one.type[0]).crownRadius_m * one.scaleXZ[0], 9.0f, 1e-3f);
  // The 3 x 3 cells whose centres lie within 9 m (the next ones are 10 m away), alike.
  int covered = 0;
  for (float c : cover) covered += c > 0.0f;
  EXPECT_EQ(covered, 9);
  const std::size_t middle = terrain.grid.index(10, 10), corner = terrain.grid.index(11, 11);
  EXPECT_NEAR(cover[middle], 1.0 - std::exp(-std::numbers::pi * 81.0 / 9.0 / 25.0), 1e-4);
  EXPECT_FLOAT_EQ(cover[corner], cover[middle]);
  // The cover never exceeds 1, and more crowns over the same ground cover more of it.
  Forest dense = one;
  for (int k = 0; k < 5; ++k) plant(dense, library, 48.0 + k, 51.0, 9.0f);
  const Field denser = canopyCover(dense, library, terrain.grid);
  const std::size_t centre = terrain.grid.index(10, 10);
  EXPECT_GT(denser[centre], cover[centre]);
  for (float c : denser) EXPECT_LE(c, 1.0f);
}

}  // namespace
}  // namespace eco
