// Analytic terrains for the sim tests.
#pragma once

#include <cmath>
#include <functional>

#include "sim/terrain.hpp"

namespace eco::test {

// height(east_m, north_m) sampled at cell centres; row 0 is the north edge.
inline Terrain analyticTerrain(int width, int height, double dx, double dy,
                               const std::function<double(double, double)>& heightAt) {
  Terrain t;
  t.grid = Grid{width, height, dx, dy};
  t.height_m.resize(t.grid.cellCount());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      t.height_m[t.grid.index(x, y)] = static_cast<float>(heightAt(x * dx, (height - 1 - y) * dy));
  return t;
}

}  // namespace eco::test
