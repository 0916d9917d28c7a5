#include "sim/ecology/dispersal.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/frames.hpp"

namespace eco {
namespace {

TEST(Dispersal, DistancesFollowTheKernelsMean) {
  LifeHistory life;
  life.dispersalMean_m = 25.0;
  Rng rng(streamKey(3, purpose("test")));
  double distance = 0.0, east = 0.0, north = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    glm::dvec2 o = seedOffset(life, {1.0, 0.0}, rng);
    distance += std::hypot(o.x, o.y);
    east += o.x, north += o.y;
  }
  EXPECT_NEAR(distance / n, 25.0, 0.25);  // standard error 25 / sqrt(n) = 0.06
  EXPECT_NEAR(east / n, 0.0, 0.3);        // no drift without wind dispersal
  EXPECT_NEAR(north / n, 0.0, 0.3);
}

TEST(Dispersal, ALongDistanceShareStretchesTheMeanDistance) {
  LifeHistory life;
  life.dispersal = DispersalVector::Animal;
  life.dispersalMean_m = 15.0;
  life.longDistanceFraction = 0.1;
  life.longDistanceMean_m = 250.0;
  Rng rng(streamKey(5, purpose("test")));
  double distance = 0.0;
  int beyond100 = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const glm::dvec2 o = seedOffset(life, {1.0, 0.0}, rng);
    distance += std::hypot(o.x, o.y);
    beyond100 += std::hypot(o.x, o.y) > 100.0;
  }
  // The mixture's mean is 0.9 x 15 + 0.1 x 250 = 38.5 m (standard error about 0.17 m); past
  // 100 m only the long-distance seeds go: 0.1 exp(-100/250) + 0.9 exp(-100/15) = 0.0682.
  EXPECT_NEAR(distance / n, 38.5, 0.8);
  EXPECT_NEAR(static_cast<double>(beyond100) / n, 0.0682, 0.002);
}

TEST(Dispersal, WindDispersedSeedsDriftDownwind) {
  LifeHistory life;
  life.dispersal = DispersalVector::Wind;
  life.dispersalMean_m = 40.0;
  life.downwindBias = 0.5;
  Rng rng(streamKey(4, purpose("test")));
  const glm::dvec2 downwind = mapDownwindOf(270.0);  // a west wind blows east
  EXPECT_NEAR(downwind.x, 1.0, 1e-12);
  EXPECT_NEAR(downwind.y, 0.0, 1e-12);
  double east = 0.0, north = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    glm::dvec2 o = seedOffset(life, downwind, rng);
    east += o.x, north += o.y;
  }
  EXPECT_NEAR(east / n, 0.5 * 40.0, 0.5);  // drift = bias x mean distance
  EXPECT_NEAR(north / n, 0.0, 0.5);
}

}  // namespace
}  // namespace eco
