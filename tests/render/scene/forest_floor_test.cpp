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
  const Field cover = canopyFloor(Forest{}, test::smallLibrary(), terrain.grid).cover();
  for (float c : cover) EXPECT_EQ(c, 0.0f);
}

TEST(CanopyCover, ACrownSmallerThanACellGoesToItsStemsCell) {
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(9, 10.0);
  Forest forest;
  plant(forest, library, 41.0, 38.0, 3.0f);  // in the cell centred at (40, 40) m
  const Field cover = canopyFloor(forest, library, terrain.grid).cover();
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
  const Field cover = canopyFloor(one, library, terrain.grid).cover();
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
  const Field denser = canopyFloor(dense, library, terrain.grid).cover();
  const std::size_t centre = terrain.grid.index(10, 10);
  EXPECT_GT(denser[centre], cover[centre]);
  for (float c : denser) EXPECT_LE(c, 1.0f);
}

TEST(CanopyFloor, ACellKeepsItsCrownsByTheTreesHeightsAndTheirMeanLeafColour) {
  const TreeLibrary& library = test::smallLibrary();  // beech, maple
  const Terrain terrain = test::flatTerrain(9, 10.0);
  Forest forest;
  // A 3 m beech and a 20 m maple by the centre of the cell at (40, 40) m, crowns within it;
  // the maple pale (its tint).
  const int beech = library.typeIndex(0, 0, 1), maple = library.typeIndex(1, 0, 1);
  forest.add(library, beech, glm::vec3(worldFromMap(41.0, 39.0, 100.0)), 3.0f, 1.0f, 1.0f, 1);
  forest.add(library, maple, glm::vec3(worldFromMap(39.0, 41.0, 100.0)), 20.0f, 2.0f, 1.0f, 2);
  forest.tint[1] = glm::vec3(1.0f, 1.0f, 0.5f);
  const CanopyFloor floor = canopyFloor(forest, library, terrain.grid);
  auto crownOf = [&](std::size_t i) {
    const float radius = library.type(forest.type[i]).crownRadius_m * forest.scaleXZ[i];
    return std::numbers::pi * radius * radius / 100.0;  // in cell areas
  };
  const std::size_t cell = terrain.grid.index(4, terrain.grid.height - 1 - 4);
  const auto& below = floor.crownsBelow[cell];
  // Tops 1, 2, 4, 8, 16, 32, 64, 128 m: the beech from 4 m on, the maple from 32.
  for (std::size_t b = 0; b < 2; ++b) EXPECT_EQ(below[b], 0.0f);
  for (std::size_t b = 2; b < 5; ++b) EXPECT_NEAR(below[b], crownOf(0), 1e-6);
  for (std::size_t b = 5; b < 8; ++b) EXPECT_NEAR(below[b], crownOf(0) + crownOf(1), 1e-6);
  EXPECT_NEAR(floor.cover()[cell], 1.0 - std::exp(-(crownOf(0) + crownOf(1))), 1e-6);
  // The colour: the species' leaf colours made linear, times each tree's tint, weighted by
  // crown area.
  auto linear = [](glm::vec3 c) {
    auto one = [](float v) {
      return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
    };
    return glm::vec3(one(c.r), one(c.g), one(c.b));
  };
  const glm::vec3 beechLeaves = linear(library.species()[0].appearance.leafColor) * forest.tint[0];
  const glm::vec3 mapleLeaves =
      linear(library.species()[1].appearance.leafColor) * glm::vec3(1.0f, 1.0f, 0.5f);
  const auto w = static_cast<float>(crownOf(0) / (crownOf(0) + crownOf(1)));
  const glm::vec3 expected = w * beechLeaves + (1.0f - w) * mapleLeaves;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(floor.leafColor[cell][c], expected[c], 1e-5f);
  // A cell without crowns is black and bare.
  EXPECT_EQ(floor.leafColor[0], glm::vec3(0.0f));
  EXPECT_EQ(floor.crownsBelow[0].back(), 0.0f);
}

}  // namespace
}  // namespace eco
