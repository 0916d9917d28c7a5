// How far a point is from the trees as they are drawn: each tree's envelope (its type's
// LOD0 reach from the stem axis per slice of height, scaled like the instance) against a
// camera. The ground preset stands where no trunk or crown is within 2 m and looks along
// the most open direction; the trees are bucketed on a grid so that a query looks at the
// trees near it only.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "render/scene/camera.hpp"
#include "render/scene/forest.hpp"

namespace eco {

// How far tree i reaches from its stem as drawn (its envelope's widest slice): a tree whose
// stem stands farther than this plus a clearance from a point, horizontally, is not within
// that clearance of it.
float drawnReach_m(const Forest& forest, std::size_t i, const TreeLibrary& library);

class TreeClearance {
 public:
  TreeClearance(const Forest& forest, const TreeLibrary& library);

  // Distance from a world point to the nearest tree's surface as drawn, or `beyond` when no
  // tree is nearer than that.
  float at(glm::vec3 point, float beyond) const;

  static constexpr float kCell_m = 8.0f;

 private:
  // Distance from a point to tree i's envelope, a stack of upright cylinders.
  float distanceTo(std::size_t i, glm::vec3 point) const;

  const Forest& forest_;
  const TreeLibrary& library_;
  float maxReach_m_ = 0.0f;  // the widest tree's reach: how far beyond a cell to look
  glm::vec2 origin_{0.0f};   // world (x, z) of cell (0, 0)
  int columns_ = 0, rows_ = 0;
  std::vector<std::uint32_t> cellStart_;  // trees of cell c: order_[cellStart_[c] .. [c + 1])
  std::vector<std::uint32_t> order_;
};

// How far a sight line from `eye` along a horizontal unit direction runs, in steps of half
// a metre, before it comes within half a metre of a tree or of the ground; at most `max_m`.
float openSight(const Terrain& terrain, const TreeClearance& trees, glm::vec3 eye,
                glm::vec3 direction, float max_m);

// The ground preset among trees: eyes 1.7 m above the ground at the point nearest the map's
// centre (on a 2 m lattice, out to 300 m) where no tree is within kGroundClearance_m and
// some bearing is open for kGroundView_m (openSight), looking along the most open bearing (the one
// nearest north among equally open ones). Without a point that clear, the clearest one.
inline constexpr float kGroundClearance_m = 2.0f;
inline constexpr float kGroundView_m = 30.0f;
Camera groundCamera(const Terrain& terrain, const Forest& forest, const TreeLibrary& library);
// Whether groundCamera may look at a tree whose stem stands at (east, north), map metres:
// within its farthest candidate, sight line and a crown's reach (kGroundCrownReach_m) of
// the map's centre, east and north. A forest of these trees alone places the camera where
// the whole forest does, so a still of a landscape need not hold the rest.
inline constexpr double kGroundCrownReach_m = 100.0;  // far beyond any species' widest crown
bool groundCameraMaySee(const Terrain& terrain, double east, double north);

// A camera kept out of the trees: raised in half-metre steps until no tree as drawn is within
// kGroundClearance_m of it, by at most kMaxLift_m; its view direction is kept. A time-lapse
// path's keys are set in one year, and trees grow into the way in later ones.
inline constexpr float kMaxLift_m = 100.0f;
Camera clearOfTrees(Camera camera, const TreeClearance& trees);

}  // namespace eco
