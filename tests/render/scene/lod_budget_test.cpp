#include "render/scene/lod_budget.hpp"

#include <cmath>
#include <functional>

#include <gtest/gtest.h>

namespace eco {
namespace {

using FrameCost = std::function<double(const LodBudget&)>;

// A frame's cost: a floor (terrain, impostors, the panel) and the meshes, whose number at
// each level grows with the area inside its switching distance, 1 / scale^2; with
// `pixels_ms`, the share of the floor that scales with the pixels drawn, resolution^2.
FrameCost frameCost(double floor_ms, double meshes_ms, double pixels_ms = 0.0) {
  return [=](const LodBudget& b) {
    const double r = b.resolution(), scale = b.scale();
    return floor_ms + pixels_ms * r * r + meshes_ms / (scale * scale);
  };
}

// Runs the budget for `frames` frames and returns the frame times of the last `tail`.
std::vector<double> run(LodBudget& budget, const FrameCost& cost, int frames, int tail) {
  std::vector<double> last;
  for (int f = 0; f < frames; ++f) {
    const double ms = cost(budget);
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
  EXPECT_DOUBLE_EQ(budget.resolution(), 1.0);  // the levels sufficed
  EXPECT_FALSE(budget.cannotReach());
  // Every size is the base times one factor: the levels keep their order.
  EXPECT_FLOAT_EQ(budget.switchPixels()[0], 600.0f * static_cast<float>(budget.scale()));
  EXPECT_FLOAT_EQ(budget.switchPixels()[2], 100.0f * static_cast<float>(budget.scale()));
}

TEST(LodBudget, CoarserTheSmallestTreesAreLeftToTheGroundUpToEightPixels) {
  // A GPU refining past the base sizes draws every tree of a pixel and more.
  LodBudget fast({600.0f, 150.0f, 150.0f}, 1000.0 / 30.0);
  run(fast, frameCost(1.0, 4.0), 40, 1);
  ASSERT_LT(fast.scale(), 1.0);
  EXPECT_EQ(fast.minPixels(), 1.0f);
  // llvmpipe coarsening: the square root of the scale, while it is under 64.
  LodBudget slow({600.0f, 150.0f, 150.0f}, 1000.0 / 30.0);
  run(slow, frameCost(10.0, 400.0), 40, 1);
  ASSERT_GT(slow.scale(), 3.0);
  ASSERT_LT(slow.scale(), LodBudget::kMaxScale);
  EXPECT_FLOAT_EQ(slow.minPixels(), static_cast<float>(std::sqrt(slow.scale())));
  // At the coarsest, 8 pixels.
  LodBudget coarsest({600.0f, 150.0f, 150.0f}, 1000.0 / 30.0);
  run(coarsest, frameCost(500.0, 400.0), 40, 1);
  ASSERT_EQ(coarsest.scale(), LodBudget::kMaxScale);
  EXPECT_EQ(coarsest.minPixels(), LodBudget::kMostMinPixels);
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

// llvmpipe with a whole run's impostors: at the coarsest levels the frame is still 6 times
// the target, nearly all of it the sprites' pixels. The levels coarsen until that stops
// paying (the meshes' share under the tolerance), then fewer pixels hold the target.
TEST(LodBudget, WhereTheCoarsestLevelsAreTooSlowFewerPixelsHoldTheTarget) {
  LodBudget budget({600.0f, 220.0f, 100.0f}, 1000.0 / 30.0);
  const FrameCost cost = frameCost(8.0, 400.0, 200.0);
  const auto times = run(budget, cost, 60, 20);
  for (double ms : times) EXPECT_NEAR(ms, budget.target_ms(), 0.2 * budget.target_ms());
  const double meshes_ms = 400.0 / (budget.scale() * budget.scale());
  EXPECT_LT(meshes_ms, LodBudget::kTolerance * times.back());
  EXPECT_GT(budget.resolution(), LodBudget::kMinResolution);
  EXPECT_LT(budget.resolution(), 0.5);
  EXPECT_FALSE(budget.cannotReach());
}

// Below the target the pixels come back before the detail: while the frame is magnified
// the levels stay as coarse as they go.
TEST(LodBudget, TheResolutionComesBackBeforeTheDetail) {
  LodBudget budget({600.0f, 220.0f, 100.0f}, 1000.0 / 30.0);
  run(budget, frameCost(8.0, 400.0, 200.0), 60, 1);
  ASSERT_LT(budget.resolution(), 0.5);
  const double coarse = budget.scale();
  const FrameCost cheaper = frameCost(2.0, 40.0, 10.0);  // species switched off
  for (int frame = 0; frame < 20 && budget.resolution() < 1.0; ++frame) {
    EXPECT_DOUBLE_EQ(budget.scale(), coarse);
    budget.update(cheaper(budget));
  }
  ASSERT_DOUBLE_EQ(budget.resolution(), 1.0);
  const auto times = run(budget, cheaper, 40, 20);
  for (double ms : times) EXPECT_NEAR(ms, budget.target_ms(), 0.2 * budget.target_ms());
  EXPECT_DOUBLE_EQ(budget.resolution(), 1.0);
  EXPECT_LT(budget.scale(), coarse);
}

TEST(LodBudget, WhereEvenTheCoarsestLevelIsTooSlowItSaysSo) {
  LodBudget budget({600.0f, 220.0f, 100.0f}, 1000.0 / 30.0);
  run(budget, frameCost(80.0, 400.0), 60, 1);  // the floor alone is 80 ms, at any resolution
  EXPECT_DOUBLE_EQ(budget.scale(), LodBudget::kMaxScale);
  EXPECT_DOUBLE_EQ(budget.resolution(), LodBudget::kMinResolution);
  EXPECT_TRUE(budget.cannotReach());
  // Once the scene gets cheaper (species switched off) it is reachable again.
  run(budget, frameCost(5.0, 400.0), 60, 1);
  EXPECT_FALSE(budget.cannotReach());
}

// Ten times the target at the start, nearly all of it pixels (a whole run's impostors on
// llvmpipe, every one drawn whatever the sizes): one coarsening of the levels shows they do
// not pay, so they keep their detail and the resolution reaches the target within five
// frames, where coarsening the levels to their coarsest first took ten (and steps of 1.5
// eleven to the coarsest levels alone).
TEST(LodBudget, ASceneThatStaysSlowIsFollowedInAFewFrames) {
  LodBudget budget({600.0f, 220.0f, 100.0f}, 1000.0 / 30.0);
  const FrameCost impostorsOnly = frameCost(10.0, 0.0, 350.0);
  const auto times = run(budget, impostorsOnly, 5, 1);
  EXPECT_DOUBLE_EQ(budget.scale(), LodBudget::kFirstStep);
  EXPECT_NEAR(times.back(), budget.target_ms(), 0.2 * budget.target_ms());
}

// Where coarser levels stop paying and even the lowest resolution is over the target, the
// levels go on to their coarsest after all: at that point every millisecond counts.
TEST(LodBudget, AtTheLowestResolutionTheLevelsCoarsenToTheEnd) {
  LodBudget budget({600.0f, 220.0f, 100.0f}, 1000.0 / 30.0);
  run(budget, frameCost(10.0, 0.0, 2000.0), 40, 1);
  EXPECT_DOUBLE_EQ(budget.resolution(), LodBudget::kMinResolution);
  EXPECT_DOUBLE_EQ(budget.scale(), LodBudget::kMaxScale);
  EXPECT_TRUE(budget.cannotReach());
}

TEST(LodBudget, OneSlowFrameMovesTheSizesByABoundedStep) {
  LodBudget budget({600.0f, 220.0f, 100.0f}, 1000.0 / 30.0);
  budget.update(5000.0);  // a snapshot loading
  EXPECT_DOUBLE_EQ(budget.scale(), 1.5);
  EXPECT_DOUBLE_EQ(budget.resolution(), 1.0);  // the levels move first
  budget.update(0.0);                          // no measurement: unchanged
  EXPECT_DOUBLE_EQ(budget.scale(), 1.5);
  budget.update(budget.target_ms() * 1.05);  // within the tolerance: unchanged
  EXPECT_DOUBLE_EQ(budget.scale(), 1.5);
  budget.update(5000.0);  // one more slow frame after one on the target: the first step again
  EXPECT_DOUBLE_EQ(budget.scale(), 1.5 * 1.5);
  budget.update(4000.0);  // two in a row, the second faster: a wider step
  EXPECT_DOUBLE_EQ(budget.scale(), 1.5 * 1.5 * 2.25);
  EXPECT_DOUBLE_EQ(budget.resolution(), 1.0);
  budget.update(3900.0);  // the coarsening saved under the tolerance: the resolution moves
  EXPECT_DOUBLE_EQ(budget.scale(), 1.5 * 1.5 * 2.25);
  EXPECT_DOUBLE_EQ(budget.resolution(), 1.0 / 3.375);
}

}  // namespace
}  // namespace eco
