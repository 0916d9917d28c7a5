// A forest's trees by place and height, made once for a forest that frames draw (`view`, a
// still): the map in square tiles, each tile's trees in groups of similar height (bands a
// fourth of an octave wide), with a box around the tile's drawn spheres and each group's
// tallest height. A frame then looks, tile by tile, only at the groups whose tallest tree is
// tall enough for a pixel at the tile's nearest point (ForestRenderer::prepare), and counts
// the others without looking at them one by one: of a landscape's 66 million plants its
// overview draws 2 million.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "render/scene/forest.hpp"
#include "render/scene/tree_library.hpp"

namespace eco {

class ForestIndex {
 public:
  static constexpr float kTile_m = 64.0f;
  // Trees trees()[first .. last) of one tile and height band; `tallest` the drawn height of
  // the tallest of them (its type's height times its vertical scale, as a frame counts it).
  struct Group {
    std::uint32_t first = 0, last = 0;
    float tallest = 0.0f;
  };
  struct Tile {
    glm::vec3 lo{0.0f}, hi{0.0f};  // a box around every drawn sphere (drawnBounds) of its trees
    std::uint32_t firstGroup = 0, lastGroup = 0;  // its groups, from the tallest band down
  };

  ForestIndex(const Forest& forest, const TreeLibrary& library);

  const std::vector<Tile>& tiles() const { return tiles_; }
  const std::vector<Group>& groups() const { return groups_; }
  // The forest's trees, tile by tile and group by group, in forest order within a group.
  const std::vector<std::uint32_t>& trees() const { return trees_; }
  // How many trees the forest it was made for holds.
  std::size_t forestSize() const { return trees_.size(); }

 private:
  std::vector<Tile> tiles_;
  std::vector<Group> groups_;
  std::vector<std::uint32_t> trees_;
};

}  // namespace eco
