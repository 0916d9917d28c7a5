#include "sim/ecology/dispersal.hpp"

#include <cmath>
#include <vector>

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

// A [[seed_source]] that surrounds the map farther than any seed flies sends what the
// surrounding forest of the same density sends.
TEST(Dispersal, ASourceRegionAroundTheMapEqualsTheSurroundingForest) {
  LifeHistory life;
  life.dispersalMean_m = 30.0;
  life.longDistanceFraction = 0.05;
  life.longDistanceMean_m = 100.0;
  // 480 m x 240 m: whole seed cells of 24 and 80 m (0.8 means), as the surrounding forest's
  // edge is the seed grid's.
  const Grid grid{48, 24, 10.0, 10.0};
  SeedMap surrounded(grid, {&life}, {1.0, 0.0}), sourced(grid, {&life}, {1.0, 0.0});
  surrounded.setSurroundingSeeds(0, 2.0);
  const int around = sourced.addSourceRegion(
      [](glm::dvec2 p) { return p.x < -5.0 || p.y < -5.0 || p.x >= 475.0 || p.y >= 235.0; });
  sourced.addRegionSeeds(around, 0, 2.0);
  surrounded.disperse();
  sourced.disperse();
  for (double east : {0.0, 100.0, 200.0, 470.0})
    for (double north : {0.0, 150.0, 230.0})
      EXPECT_NEAR(sourced.density(0, east, north), surrounded.density(0, east, north),
                  1e-6 * surrounded.density(0, east, north));
}

// A forest west of the map: its seeds land on the map as far as the kernel carries them. At a
// distance d from the forest's edge an even source of S seeds per m2 gives S P(X > d), X the
// kernel's east-west offset, averaged over the target cell (here by sampling the kernel anew).
TEST(Dispersal, SeedsFromASourceOffTheMapLandAtTheKernelsDistances) {
  LifeHistory life;
  life.dispersal = DispersalVector::Animal;
  life.dispersalMean_m = 50.0;          // seed cells of 40 m
  const Grid grid{80, 20, 10.0, 10.0};  // 800 m x 200 m, its west edge at east = -5 m
  SeedMap seeds(grid, {&life}, {1.0, 0.0});
  const int forest = seeds.addSourceRegion([](glm::dvec2 p) { return p.x < -5.0; });
  seeds.addRegionSeeds(forest, 0, 2.0);
  seeds.disperse();
  Rng rng(streamKey(11, purpose("test")));
  const int n = 1000000;
  for (int cell = 0; cell < 5; ++cell) {
    int landed = 0;
    for (int k = 0; k < n; ++k) {
      const double d = (cell + rng.uniform()) * 40.0;  // target, metres from the edge
      const glm::dvec2 o = seedOffsetFrom(life, false, {1.0, 0.0}, rng);
      landed += o.x > d && std::hypot(o.x, o.y) <= 5.0 * 50.0;  // the stencil reaches 5 means
    }
    const double expected = 2.0 * landed / n;
    const double east = -5.0 + (cell + 0.5) * 40.0;
    EXPECT_NEAR(seeds.density(0, east, 100.0), expected, 0.03 * expected + 1e-4) << "cell " << cell;
  }
  EXPECT_LT(seeds.density(0, 700.0, 100.0), 1e-6);  // 14 means away: no seed
}

// Establishment asks for the seeds at millions of regeneration cells a year, which lie on a
// lattice: looked up through the lattice's columns and rows, each layer's cell is the one
// the place's own lookup finds, so the density is the same to the bit, on the map, on its
// edges and beyond them (clamped to the edge cells).
TEST(Dispersal, ALatticeOfPlacesFindsEachPlacesOwnSeeds) {
  LifeHistory pine, beech;
  pine.dispersalMean_m = 40.0;
  beech.dispersal = DispersalVector::Animal;
  beech.dispersalMean_m = 15.0;
  beech.longDistanceFraction = 0.1;
  beech.longDistanceMean_m = 200.0;  // a second layer on its own grid
  const Grid grid{60, 40, 10.0, 10.0};
  SeedMap seeds(grid, {&pine, &beech}, {1.0, 0.0});
  seeds.setSurroundingSeeds(0, 0.5);
  Rng rng(streamKey(13, purpose("test")));
  for (int k = 0; k < 200; ++k)
    seeds.addSeeds(k % 2, rng.uniform() * 590.0, rng.uniform() * 390.0, 1000.0 * rng.uniform());
  seeds.disperse();
  std::vector<double> easts, norths;
  for (double east = -20.0; east < 620.0; east += 2.0 / 3.0) easts.push_back(east);
  for (double north = -20.0; north < 420.0; north += 2.0) norths.push_back(north);
  const SeedMap::Lattice lattice = seeds.latticeOf(easts, norths);
  int seeded = 0;
  for (int species = 0; species < 2; ++species)
    for (std::size_t y = 0; y < norths.size(); ++y)
      for (std::size_t x = 0; x < easts.size(); ++x) {
        const double own = seeds.density(species, easts[x], norths[y]);
        ASSERT_EQ(seeds.density(species, lattice, static_cast<int>(x), static_cast<int>(y)), own)
            << species << " at " << easts[x] << ", " << norths[y];
        seeded += own > 0.0;
      }
  EXPECT_GT(seeded, 0);
}

}  // namespace
}  // namespace eco
