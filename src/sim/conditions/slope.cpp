#include "sim/conditions/slope.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "core/angles.hpp"
#include "sim/terrain_mesh.hpp"

namespace eco {

void computeSlopeAspect(const Terrain& terrain, Field& slope_deg, Field& aspect_deg) {
  const Grid& g = terrain.grid;
  slope_deg.assign(g.cellCount(), 0.0f);
  aspect_deg.assign(g.cellCount(), -1.0f);
  tbb::parallel_for(0, g.height, [&](int y) {
    for (int x = 0; x < g.width; ++x) {
      Gradient d = terrainGradient(terrain, x, y);
      double steepness = std::hypot(d.east, d.north);
      slope_deg[g.index(x, y)] = static_cast<float>(degrees(std::atan(steepness)));
      if (steepness < 1e-9) continue;
      double aspect = degrees(std::atan2(-d.east, -d.north));  // downhill, clockwise from north
      aspect_deg[g.index(x, y)] = static_cast<float>(aspect < 0.0 ? aspect + 360.0 : aspect);
    }
  });
}

}  // namespace eco
