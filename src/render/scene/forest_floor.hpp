// What the ground under a forest looks like from the trees standing on it: the share of
// each terrain cell under crowns, from which the terrain shader mixes open grass into leaf
// litter and moss (docs/rendering.md, "Terrain"). Computed from the trees as drawn, so it
// follows a run's snapshot, a time-lapse frame or a demo planting alike.
#pragma once

#include "render/scene/forest.hpp"
#include "sim/grid.hpp"

namespace eco {

// Each tree's crown (its drawn radius, times its presence) is spread evenly over the cells
// whose centres its disc covers (the stem's cell when it covers none), and the crown area
// a cell receives becomes a cover of 1 - exp(-area / cell area): crowns placed at random
// overlap, so twice a cell's area in crowns covers 86 % of it, not all of it. 0..1 per cell.
Field canopyCover(const Forest& forest, const TreeLibrary& library, const Grid& grid);

}  // namespace eco
