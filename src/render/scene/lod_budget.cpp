#include "render/scene/lod_budget.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace eco {

LodBudget::LodBudget(std::array<float, 3> baseSwitchPixels, double targetFrame_ms)
    : base_(baseSwitchPixels), target_ms_(targetFrame_ms) {
  ECO_ASSERT(targetFrame_ms > 0.0, "frame-time target " << targetFrame_ms);
}

void LodBudget::update(double frame_ms) {
  if (!(frame_ms > 0.0)) return;  // no measurement (the first frame, a minimised window)
  const double ratio = frame_ms / target_ms_;
  // The last coarsening saved less than the tolerance: what is left of the frame is what the
  // levels do not change (on llvmpipe, a whole run's impostors), so the resolution moves
  // next instead of detail thrown away for nothing, at seconds a frame.
  if (coarsenedLevels_ && frame_ms > lastFrame_ms_ * (1.0 - kTolerance)) levelsSpent_ = true;
  coarsenedLevels_ = false;
  lastFrame_ms_ = frame_ms;
  const bool coarsest = scale_ >= kMaxScale;
  cannotReach_ = coarsest && resolution_ <= kMinResolution && ratio > 1.0 + kTolerance;
  if (std::abs(ratio - 1.0) <= kTolerance) {
    streak_ = 0;
    return;
  }
  // A frame's cost falls roughly with the square of the switching distances' inverse (the
  // trees at a level fill an area), and with the square of the resolution (the pixels), so
  // the square root of the ratio moves either about to the target in one step. The step is
  // capped so that one slow frame (a snapshot loading) does not throw the detail away, and
  // the cap widens with each frame in a row on the same side of the target, so that a scene
  // that stays slow (seconds a frame on llvmpipe) is followed in a few frames, not dozens.
  const int side = ratio > 1.0 ? 1 : -1;
  streak_ = streak_ * side > 0 ? streak_ + side : side;
  const double cap = std::min(std::pow(kFirstStep, std::abs(streak_)), kLargestStep);
  const double step = std::clamp(std::sqrt(ratio), 1.0 / cap, cap);
  // Over the target: coarser levels first, then fewer pixels (sooner where the levels
  // stopped paying; at the lowest resolution the levels go on to their coarsest). Under it:
  // the pixels back first (a magnified picture blurs every tree), then finer levels.
  const bool resolutionMoves =
      ratio > 1.0 ? coarsest || (levelsSpent_ && resolution_ > kMinResolution) : resolution_ < 1.0;
  if (resolutionMoves) {
    resolution_ = std::clamp(resolution_ / step, kMinResolution, 1.0);
    return;
  }
  scale_ = std::clamp(scale_ * step, kMinScale, kMaxScale);
  coarsenedLevels_ = ratio > 1.0;
  if (ratio < 1.0) levelsSpent_ = false;
}

float LodBudget::minPixels() const {
  return std::clamp(static_cast<float>(std::sqrt(scale_)), 1.0f, kMostMinPixels);
}

std::array<float, 3> LodBudget::switchPixels() const {
  std::array<float, 3> sizes{};
  for (int level = 0; level < 3; ++level) sizes[level] = static_cast<float>(base_[level] * scale_);
  return sizes;
}

}  // namespace eco
