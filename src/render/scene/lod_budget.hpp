// The level-of-detail distances `ecoforest view` chooses each frame to hold a frame-time
// target: one factor scales every switching size of the quality it starts from. Above the
// target it grows (coarser levels nearer), below it shrinks (finer levels farther out), so
// a GPU shows LOD0 far out and llvmpipe stays interactive. Where even the coarsest levels
// are over the target, the frame is drawn at a lower resolution and magnified (dynamic
// resolution, as game engines hold their frame rate), its shadow maps with it, and so it is
// where coarser levels stopped paying: a frame that a coarsening left within the tolerance
// of the one before (a scene of impostors, which every level draws alike). Coarser, the
// smallest trees are left to the ground as well (minPixels()). Below the target
// the resolution comes back first, before the detail. Apart from any window or OpenGL, so
// that it can be tested with a model of a frame's cost.
#pragma once

#include <array>

namespace eco {

class LodBudget {
 public:
  // The switching sizes of the quality the view starts from, and the frame time to hold.
  LodBudget(std::array<float, 3> baseSwitchPixels, double targetFrame_ms);

  // The time the frame drawn with switchPixels() took; sets the sizes for the next one.
  void update(double frame_ms);

  std::array<float, 3> switchPixels() const;
  // The trees under this many pixels are not drawn (LodSettings::minPixels) and the ground
  // shows their crowns (forest_floor.hpp): 1 up to the base sizes, then the square root of
  // the scale (the distance at which a tree is dropped moves with the switching distances'
  // square root, as a frame's cost does), up to kMostMinPixels at the coarsest.
  float minPixels() const;
  double scale() const { return scale_; }
  // The share of the window's width and height the frame is drawn at, kMinResolution..1.
  double resolution() const { return resolution_; }
  double target_ms() const { return target_ms_; }
  // The sizes are as coarse as they go, the resolution as low, and the last frame was
  // still over the target by more than the tolerance: the frame time shown is the best
  // this scene reaches.
  bool cannotReach() const { return cannotReach_; }

  // Frames within this share of the target leave the sizes alone (no hunting on noise).
  static constexpr double kTolerance = 0.1;
  // The most a frame moves the sizes or the resolution by: kFirstStep after one frame off
  // the target, its powers after several in a row on the same side, up to kLargestStep.
  static constexpr double kFirstStep = 1.5, kLargestStep = 4.0;
  // At the finest, LOD0 reaches trees 1/16 of the base size; at the coarsest every mesh
  // level is 64 times farther in (a balanced 600-pixel LOD0 switch becomes 38,400 pixels:
  // nothing but impostors).
  static constexpr double kMinScale = 1.0 / 16.0, kMaxScale = 64.0;
  // Measured on the valley run's `low` view at balanced (960 x 540, docs/rendering.md "`view`
  // holds a frame-time target"): the trees under 8 pixels left to the ground change the
  // picture by 0.4 of 255 (a million sprites fewer), under 16 by 3.4, the far canopy flat.
  static constexpr float kMostMinPixels = 8.0f;
  // A quarter of the width and height: 320 x 180 pixels of a 1280 x 720 window, a sixteenth
  // of the fragments, still a picture one can steer by.
  static constexpr double kMinResolution = 0.25;

 private:
  std::array<float, 3> base_;
  double target_ms_;
  double scale_ = 1.0;
  double resolution_ = 1.0;
  int streak_ = 0;  // frames in a row over (> 0) or under (< 0) the target
  bool cannotReach_ = false;
  double lastFrame_ms_ = 0.0;
  bool coarsenedLevels_ = false;  // the last update coarsened the levels
  // Coarsening the levels no longer paid; cleared when they are refined again.
  bool levelsSpent_ = false;
};

}  // namespace eco
