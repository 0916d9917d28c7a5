// A plan's region placed on a terrain (docs/planning.md): which map positions it holds.
// Polygons use the even-odd rule; a buffer widens any shape by a distance; a mask is read
// once and widened cell by cell.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "sim/grid.hpp"
#include "sim/plan/plan_spec.hpp"
#include "sim/terrain.hpp"

namespace eco {

// The map's extent in map metres: cell (x, y) covers [east - dx/2, east + dx/2].
struct MapBounds {
  glm::dvec2 min, max;
  static MapBounds of(const Grid& grid);
  bool contains(glm::dvec2 p) const {
    return p.x >= min.x && p.y >= min.y && p.x < max.x && p.y < max.y;
  }
};

class Region {
 public:
  // Places a rule's region on the grid. A mask of another size than the terrain, and (unless
  // `mayLieOutside`, for seed sources) a shape that misses the map, are InputErrors at the
  // scenario line that gave the shape.
  Region(const RegionSpec& spec, const Grid& grid, bool mayLieOutside = false);

  bool contains(glm::dvec2 p) const;
  // A box around what it holds: within the map, except for a seed source's shape or
  // border, which may reach beyond it.
  MapBounds bounds() const { return bounds_; }
  // The area of its landscape cells (cell centres inside, outside no-data), m2: the area
  // stand measures of the region are per.
  double areaOnLandscape_m2(const Terrain& terrain) const;

 private:
  bool insideShape(glm::dvec2 p) const;
  double distanceToOutline(glm::dvec2 p) const;

  RegionSpec spec_;
  Grid grid_;
  MapBounds bounds_;
  MapBounds map_;
  std::vector<std::uint8_t> mask_;  // Mask: per cell, already widened by the buffer
};

}  // namespace eco
