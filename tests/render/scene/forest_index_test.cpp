#include "render/scene/forest_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "render_support.hpp"

namespace eco {
namespace {

// A planting of every height over a map of several tiles.
Forest planted() {
  const Terrain terrain = test::flatTerrain(65, 10.0);
  return demoForest(terrain, test::smallLibrary(), 3000, 7);
}

TEST(ForestIndex, HoldsEveryTreeOnceByTileAndHeight) {
  const Forest forest = planted();
  const TreeLibrary& library = test::smallLibrary();
  const ForestIndex index(forest, library);
  ASSERT_EQ(index.forestSize(), forest.size());
  std::vector<std::uint32_t> all = index.trees();
  std::sort(all.begin(), all.end());
  for (std::size_t i = 0; i < all.size(); ++i) ASSERT_EQ(all[i], i);
  EXPECT_GT(index.tiles().size(), 20u);  // 640 m across in tiles of 64 m
  std::uint32_t nextGroup = 0, nextTree = 0;
  std::size_t bands = 0;
  for (const ForestIndex::Tile& tile : index.tiles()) {
    EXPECT_EQ(tile.firstGroup, nextGroup);  // the tiles cover groups() in order
    EXPECT_LT(tile.firstGroup, tile.lastGroup);
    nextGroup = tile.lastGroup;
    bands += tile.lastGroup - tile.firstGroup;
    float lowest = std::numeric_limits<float>::max();  // of the band above
    for (std::uint32_t g = tile.firstGroup; g < tile.lastGroup; ++g) {
      const ForestIndex::Group& group = index.groups()[g];
      EXPECT_EQ(group.first, nextTree);  // the groups cover trees() in order
      EXPECT_LT(group.first, group.last);
      nextTree = group.last;
      float tallest = 0.0f, shortest = std::numeric_limits<float>::max();
      for (std::uint32_t k = group.first; k < group.last; ++k) {
        const std::uint32_t i = index.trees()[k];
        if (k > group.first) {
          EXPECT_LT(index.trees()[k - 1], i);  // forest order
        }
        const TreeType& type = library.type(forest.type[i]);
        const float height = type.height_m * forest.scaleY[i];
        tallest = std::max(tallest, height), shortest = std::min(shortest, height);
        // Its drawn sphere inside the tile's box.
        const glm::vec4 bounds = drawnBounds(forest, i, type);
        for (int axis = 0; axis < 3; ++axis) {
          EXPECT_GE(bounds[axis] - bounds.w, tile.lo[axis]);
          EXPECT_LE(bounds[axis] + bounds.w, tile.hi[axis]);
        }
      }
      EXPECT_EQ(group.tallest, tallest);
      EXPECT_LT(tallest, lowest);                                    // bands from the tallest down
      EXPECT_LE(tallest, shortest * std::pow(2.0f, 0.25f) + 1e-4f);  // a fourth of an octave
      lowest = shortest;
    }
  }
  EXPECT_EQ(nextTree, forest.size());
  EXPECT_GT(bands, 2 * index.tiles().size());  // each tile holds trees of several heights
}

TEST(ForestIndex, OfNoTreesHasNoTiles) {
  const ForestIndex index(Forest{}, test::smallLibrary());
  EXPECT_TRUE(index.tiles().empty());
  EXPECT_EQ(index.forestSize(), 0u);
}

}  // namespace
}  // namespace eco
