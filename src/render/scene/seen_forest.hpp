// The trees a frame can show, chosen as they are made: a landscape's snapshot holds a hundred
// million plants, of which a still from `overview` draws two million. The others are under a
// pixel (LodSettings::minPixels) wherever the frame is drawn from, so they are neither drawn
// nor cast a shadow, and only the forest floor shows their crowns (docs/rendering.md, "Only
// the trees a pixel can show"). A still of a run and each growth time-lapse frame keep these
// trees and their floor, never the whole forest.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "render/scene/camera.hpp"
#include "render/scene/culling.hpp"
#include "render/scene/forest.hpp"
#include "render/scene/forest_floor.hpp"
#include "render/scene/frame_size.hpp"

namespace eco {

struct SeenForest {
  Forest shown;       // the trees that may be drawn or cast a shadow, in the forest's order
  CanopyFloor floor;  // of every tree, shown or not
  // The trees left out, as the renderer counts those it does not draw (ForestStats):
  // outside the frustum, or within it under minPixels.
  std::size_t culled = 0, tooSmall = 0;
};

// Whether tree i, of `type`, may be drawn or cast a shadow from an eye at `eye` or up to
// `nearer_m` nearer to it (mayReachMinPixels at its drawn sphere's centre, drawnBounds): a
// tree left out is under minPixels in the renderer too.
bool mayBeDrawn(const Forest& forest, std::size_t i, const TreeType& type, glm::vec3 eye,
                float pixelsPerRadian, const LodSettings& lod, float nearer_m = 0.0f);

// What a frame does with a tree it was handed.
enum class TreeSeen : std::uint8_t { Shown, Culled, TooSmall };

// A frame's trees kept a part at a time: every part's crowns go into the floor, its trees
// `seen` calls Shown into the forest shown (in order), and the others are counted.
class SeenForestSum {
 public:
  SeenForestSum(const TreeLibrary& library, const Grid& grid) : floor_(library, grid) {}
  // `seen(i)` for tree i of `part`, asked side by side.
  void add(const Forest& part, const std::function<TreeSeen(std::size_t)>& seen);
  SeenForest done() &&;

 private:
  CanopyFloorSum floor_;
  SeenForest seen_;
  std::vector<TreeSeen> verdicts_;  // the part's, kept from part to part
};

// A run's trees of `year` that a still of `frame` from `camera` at `lod` can show, read a
// batch of rows at a time (forEachForestBatch), with the floor of all of them. Drawn, they
// give the same picture and counts as the whole year's forest.
SeenForest forestSeenFrom(const RunFolder& run, int year, const TreeLibrary& library,
                          const Grid& grid, const Camera& camera, FrameSize frame,
                          const LodSettings& lod);
// A forest held whole (a demo planting; a year the camera was placed in) and its floor.
SeenForest wholeForest(Forest forest, const TreeLibrary& library, const Grid& grid);

}  // namespace eco
