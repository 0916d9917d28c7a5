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
  cannotReach_ = scale_ >= kMaxScale && ratio > 1.0 + kTolerance;
  if (std::abs(ratio - 1.0) <= kTolerance) return;
  // A frame's cost falls roughly with the square of the switching distances' inverse (the
  // trees at a level fill an area), so the square root of the ratio moves the sizes about
  // to the target in one step; the step is capped so that one slow frame (a snapshot
  // loading) does not throw the detail away.
  const double step = std::clamp(std::sqrt(ratio), 1.0 / 1.5, 1.5);
  scale_ = std::clamp(scale_ * step, kMinScale, kMaxScale);
}

std::array<float, 3> LodBudget::switchPixels() const {
  std::array<float, 3> sizes{};
  for (int level = 0; level < 3; ++level) sizes[level] = static_cast<float>(base_[level] * scale_);
  return sizes;
}

}  // namespace eco
