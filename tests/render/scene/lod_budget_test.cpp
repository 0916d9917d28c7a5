#include "render/scene/lod_budget.hpp"

#include <cmath>
#include <functional>

#include <gtest/gtest.h>

namespace eco {
namespace {

// A frame's cost: a floor (terrain, impostors, the panel) and the meshes, whose number at
// each level grows with the area inside its switching distance, 1 / scale^2.
std::function<double(double)> frameCost(double floor_ms, double meshes_ms) {
  return [=](double scale) { return floor_ms + meshes_ms / (scale * scale); };
}

// Runs the budget for `frames` frames and returns the frame times of the last `tail`.
std::vector<double> run(LodBudget& budget, const std::function<double(double)>& cost, int frames,
                        int tail) {
  std::vector<double> last;
  for (int f = 0; f < frames; ++f) {
    const double ms = cost(budget.scale());
    if (f >= frames - tail) last.push_back(ms);
    budget.update(ms);
  }
  return last;
}

TEST(LodBudget, ASlowSceneIsCoarsenedUntilItHoldsTheTargetWithinTwentyPercent) {
  LodBudget budget({600.0f, 220.0f, 100.0f}, 1000.0 / 30.0);
  // llvmpipe-like: 410 ms a frame at the balanced sizes.
  const auto times = run(budget, frameCost(10.0, 400.0), 40, 20);
  for (double ms : times) EXPECT_NEAR(ms, budget.target_ms(), 0.2 * budget.target_ms());
  EXPECT_GT(budget.scale(), 3.0);
  EXPECT_FALSE(budget.cannotReach());
  // Every size is the base times one factor: the levels keep their order.
  EXPECT_FLOAT_EQ(budget.switchPixels()[0], 600.0f * static_cast<float>(budget.scale()));
  EXPECT_FLOAT_EQ(budget.switchPixels()[2], 100.0f * static_cast<float>(budget.scale()));
}

TEST(LodBudget, AFastSceneShowsFullDetailFartherOut) {
  LodBudget budget({600.0f, 220.0f, 100.0f}, 1000.0 / 30.0);
  const auto times = run(budget, frameCost(1.0, 4.0), 40, 20);  // a GPU: 5 ms at the base
  for (double ms : times) EXPECT_NEAR(ms, budget.target_ms(), 0.2 * budget.target_ms());
  EXPECT_LT(budget.scale(), 0.5);
  // With nothing left to refine it stops at the finest sizes, under the target.
  LodBudget idle({600.0f, 220.0f, 100.0f}, 1000.0 / 30.0);
  run(idle, frameCost(1.0, 0.0), 40, 1);
  EXPECT_DOUBLE_EQ(idle.scale(), LodBudget::kMinScale);
  EXPECT_FALSE(idle.cannotReach());
}

TEST(LodBudget, WhereEvenTheCoarsestLevelIsTooSlowItSaysSo) {
  LodBudget budget({600.0f, 220.0f, 100.0f}, 1000.0 / 30.0);
  run(budget, frameCost(80.0, 400.0), 60, 1);  // the floor alone is 80 ms
  EXPECT_DOUBLE_EQ(budget.scale(), LodBudget::kMaxScale);
  EXPECT_TRUE(budget.cannotReach());
  // Once the scene gets cheaper (species switched off) it is reachable again.
  run(budget, frameCost(5.0, 400.0), 60, 1);
  EXPECT_FALSE(budget.cannotReach());
}

TEST(LodBudget, OneSlowFrameMovesTheSizesByABoundedStep) {
  LodBudget budget({600.0f, 220.0f, 100.0f}, 1000.0 / 30.0);
  budget.update(5000.0);  // a snapshot loading
  EXPECT_DOUBLE_EQ(budget.scale(), 1.5);
  budget.update(0.0);  // no measurement: unchanged
  EXPECT_DOUBLE_EQ(budget.scale(), 1.5);
  budget.update(budget.target_ms() * 1.05);  // within the tolerance: unchanged
  EXPECT_DOUBLE_EQ(budget.scale(), 1.5);
}

}  // namespace
}  // namespace eco
