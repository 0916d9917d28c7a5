// Slope and aspect of every cell from the terrain's gradient (terrain_mesh.hpp: Horn's
// finite differences), the same surface the renderer shades.
#pragma once

#include "sim/terrain.hpp"

namespace eco {

// aspect: compass bearing the slope faces (downhill), degrees in [0, 360); -1 where flat.
void computeSlopeAspect(const Terrain& terrain, Field& slope_deg, Field& aspect_deg);

}  // namespace eco
