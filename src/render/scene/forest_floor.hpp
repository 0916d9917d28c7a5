// What the ground under a forest looks like from the trees standing on it: the share of
// each terrain cell under crowns, from which the terrain shader mixes open grass into leaf
// litter and moss (docs/rendering.md, "Terrain"), and the crowns themselves where they are
// too small to draw (docs/rendering.md, "The canopy too small to draw"). Computed from the
// trees as drawn, so it follows a run's snapshot, a time-lapse frame or a demo planting alike.
#pragma once

#include <array>
#include <vector>

#include <glm/ext/vector_double3.hpp>
#include <glm/vec3.hpp>

#include "render/scene/forest.hpp"
#include "sim/grid.hpp"

namespace eco {

// The heights (m) by which the crowns of a cell are told apart: a tree shorter than a pixel
// at a fragment's distance is not drawn, and the ground there shows the crowns of the trees
// under that height. Doubling, so that the height of a cut is read to within a factor of 2
// between them; the last is above any tree.
inline constexpr std::array<float, 8> kCanopyHeightTops_m{1, 2, 4, 8, 16, 32, 64, 128};

// Each tree's crown (its drawn radius, times its presence) is spread evenly over the cells
// whose centres its disc covers (the stem's cell when it covers none).
struct CanopyFloor {
  // Per cell, the crown area of the trees shorter than each of kCanopyHeightTops_m, in cell
  // areas: a running sum, the last of every tree's crowns.
  std::vector<std::array<float, kCanopyHeightTops_m.size()>> crownsBelow;
  // Per cell, the crowns' mean leaf colour (linear RGB: the species' leaf colour times each
  // tree's tint), weighted by crown area; black where there are none.
  std::vector<glm::vec3> leafColor;

  // The share of each cell under crowns, 1 - exp(-area / cell area): crowns placed at random
  // overlap, so twice a cell's area in crowns covers 86 % of it, not all of it. 0..1 per cell.
  Field cover() const;
};

CanopyFloor canopyFloor(const Forest& forest, const TreeLibrary& library, const Grid& grid);

// The same summed over forests added one after another (a frame made in parts): the floor of
// their trees together, the same to the bit as canopyFloor of one forest holding them all in
// that order.
class CanopyFloorSum {
 public:
  CanopyFloorSum(const TreeLibrary& library, const Grid& grid);
  void add(const Forest& forest);
  CanopyFloor floor() const;

 private:
  const TreeLibrary& library_;
  const Grid& grid_;
  std::vector<glm::vec3> leafColors_;                                 // [species], linear
  std::vector<std::array<double, kCanopyHeightTops_m.size()>> area_;  // [cell][height band]
  std::vector<glm::dvec3> colour_;  // [cell]: the crowns' colours times their areas
};

}  // namespace eco
