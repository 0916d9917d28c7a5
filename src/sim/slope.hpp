// Slope and aspect by Horn's (1981) third-order finite differences on the 3 x 3
// neighbourhood, with separate east-west and north-south cell sizes. Past the edges the
// surface is continued linearly, so edge cells keep the local gradient.
#pragma once

#include "sim/terrain.hpp"

namespace eco {

// aspect: compass bearing the slope faces (downhill), degrees in [0, 360); -1 where flat.
void computeSlopeAspect(const Terrain& terrain, Field& slope_deg, Field& aspect_deg);

// The height gradient of a cell: dz/dx east and dz/dy north, metres per metre.
struct Gradient {
  double east = 0.0;
  double north = 0.0;
};
Gradient hornGradient(const Terrain& terrain, int x, int y);

}  // namespace eco
