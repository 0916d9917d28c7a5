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

// A map much smaller than the kernel, set in a uniform forest: nearly every seed landing on it
// comes from outside (less the few that would have come from the map itself, here about
// 7 %), and an even source spreads into an even density of the same seeds per m2.
TEST(Dispersal, TheSurroundingForestSendsItsSeedsAcrossTheEdges) {
  LifeHistory life;
  life.dispersalMean_m = 2000.0;
  SeedMap small(Grid{30, 30, 10.0, 10.0}, {&life}, {1.0, 0.0});
  small.setSurroundingSeeds(0, 3.0);
  small.disperse();
  EXPECT_NEAR(small.density(0, 150.0, 150.0), 3.0, 0.3);
  EXPECT_LE(small.density(0, 150.0, 150.0), 3.0);
  // On a map 20 kernel means across, the forest's seeds stay near its edges.
  LifeHistory beech;
  beech.dispersalMean_m = 20.0;
  SeedMap wide(Grid{81, 81, 5.0, 5.0}, {&beech}, {1.0, 0.0});
  wide.setSurroundingSeeds(0, 3.0);
  wide.disperse();
  EXPECT_GT(wide.density(0, 2.0, 200.0), 0.5);     // at the western edge
  EXPECT_LT(wide.density(0, 200.0, 200.0), 1e-6);  // 10 means in
  // A new year starts without them.
  wide.clear();
  wide.disperse();
  EXPECT_EQ(wide.density(0, 2.0, 200.0), 0.0);
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
