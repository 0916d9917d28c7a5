// The level-of-detail distances `ecoforest view` chooses each frame to hold a frame-time
// target: one factor scales every switching size of the quality it starts from. Above the
// target it grows (coarser levels nearer), below it shrinks (finer levels farther out), so
// a GPU shows LOD0 far out and llvmpipe stays interactive. Apart from any window or OpenGL,
// so that it can be tested with a model of a frame's cost.
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
  double scale() const { return scale_; }
  double target_ms() const { return target_ms_; }
  // The sizes are as coarse as they go and the last frame was still over the target by
  // more than the tolerance: the frame time shown is the best this scene reaches.
  bool cannotReach() const { return cannotReach_; }

  // Frames within this share of the target leave the sizes alone (no hunting on noise).
  static constexpr double kTolerance = 0.1;
  // At the finest, LOD0 reaches trees 1/16 of the base size; at the coarsest every mesh
  // level is 64 times farther in (a balanced 600-pixel LOD0 switch becomes 38,400 pixels:
  // nothing but impostors).
  static constexpr double kMinScale = 1.0 / 16.0, kMaxScale = 64.0;

 private:
  std::array<float, 3> base_;
  double target_ms_;
  double scale_ = 1.0;
  bool cannotReach_ = false;
};

}  // namespace eco
