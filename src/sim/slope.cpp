#include "sim/slope.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <tbb/parallel_for.h>

#include "core/angles.hpp"

namespace eco {

namespace {

// Height at (x, y), continued linearly past the edges (2 z_edge - z_inside) so that edge
// cells of a plane get the plane's exact gradient.
double extendedHeight(const Terrain& terrain, int x, int y) {
  const Grid& g = terrain.grid;
  if (x < 0) return 2.0 * extendedHeight(terrain, 0, y) - extendedHeight(terrain, -x, y);
  if (x >= g.width)
    return 2.0 * extendedHeight(terrain, g.width - 1, y) -
           extendedHeight(terrain, 2 * (g.width - 1) - x, y);
  if (y < 0) return 2.0 * extendedHeight(terrain, x, 0) - extendedHeight(terrain, x, -y);
  if (y >= g.height)
    return 2.0 * extendedHeight(terrain, x, g.height - 1) -
           extendedHeight(terrain, x, 2 * (g.height - 1) - y);
  return terrain.heightAt(x, y);
}

}  // namespace

Gradient hornGradient(const Terrain& terrain, int x, int y) {
  const Grid& g = terrain.grid;
  auto z = [&](int dx, int dy) { return extendedHeight(terrain, x + dx, y + dy); };
  // Row -1 is the northern neighbour row (row 0 of the grid is the north edge).
  double east = ((z(1, -1) + 2.0 * z(1, 0) + z(1, 1)) - (z(-1, -1) + 2.0 * z(-1, 0) + z(-1, 1))) /
                (8.0 * g.dx_m);
  double north = ((z(-1, -1) + 2.0 * z(0, -1) + z(1, -1)) - (z(-1, 1) + 2.0 * z(0, 1) + z(1, 1))) /
                 (8.0 * g.dy_m);
  return {east, north};
}

void computeSlopeAspect(const Terrain& terrain, Field& slope_deg, Field& aspect_deg) {
  const Grid& g = terrain.grid;
  slope_deg.assign(g.cellCount(), 0.0f);
  aspect_deg.assign(g.cellCount(), -1.0f);
  tbb::parallel_for(0, g.height, [&](int y) {
    for (int x = 0; x < g.width; ++x) {
      Gradient d = hornGradient(terrain, x, y);
      double steepness = std::hypot(d.east, d.north);
      slope_deg[g.index(x, y)] = static_cast<float>(degrees(std::atan(steepness)));
      if (steepness < 1e-9) continue;
      double aspect = degrees(std::atan2(-d.east, -d.north));  // downhill, clockwise from north
      aspect_deg[g.index(x, y)] = static_cast<float>(aspect < 0.0 ? aspect + 360.0 : aspect);
    }
  });
}

}  // namespace eco
