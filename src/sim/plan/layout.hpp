// Where a [[planting]] puts its trees (docs/planning.md, "Layouts"): a square (or
// rectangular) grid, a triangular grid, rows along the contour lines, or random positions no
// closer than a minimum distance. Grids are anchored at the map's south-west corner, so
// neighbouring plantings with one spacing line up.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "sim/plan/plan_spec.hpp"
#include "sim/plan/region.hpp"
#include "sim/terrain.hpp"

namespace eco {

struct PlantingSpot {
  glm::dvec2 position;  // map metres
  int row = 0;          // its row (grids and contours), for a row pattern of species
};

struct PlantingLayoutResult {
  std::vector<PlantingSpot> spots;  // inside the region, on the landscape
  std::string note;  // why the layout fell back to another, for the user; empty if it did not
};

// The mean slope (rise over run) of the landscape cells inside the region.
double meanGradient(const Terrain& terrain, const Region& region);

// The spots of a planting in its region. Contour rows lie on contour lines row_spacing_m
// apart where the region's ground has its mean slope (Δh = row spacing × mean gradient), with
// trees every spacing_m along them; on ground flatter than 1 % they fall back to a square
// grid. The random layout draws darts (seeded by `seed`) until it holds area / spacing²
// trees or gives up after 30 tries a tree.
PlantingLayoutResult layoutPlanting(const Planting& planting, const Region& region,
                                    const Terrain& terrain, std::uint64_t seed);

}  // namespace eco
