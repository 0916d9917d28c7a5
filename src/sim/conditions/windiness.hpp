// Exposure to the prevailing wind (docs/conditions.md): Winstral et al.'s (2002) upwind
// maximum slope Sx -- the steepest angle up to the terrain upwind within a search distance,
// averaged over three directions across a 30-degree sector -- combined with altitude.
// Sx > 0 means higher ground upwind: a lee, sheltered cell; Sx < 0 an exposed one.
#pragma once

#include "sim/terrain.hpp"

namespace eco {

inline constexpr double kWindSearch_m = 500.0;  // how far upwind Sx looks

// Winstral's Sx in degrees for every cell; `from_deg` is the compass bearing the wind comes from.
Field upwindSlope(const Terrain& terrain, double from_deg, double searchDistance_m = kWindSearch_m);

// windiness = 0.7 * clamp(0.5 - Sx / 30 deg, 0, 1) + 0.3 * (altitude - lowest) / relief.
void computeWindiness(const Terrain& terrain, double from_deg, Field& windiness);

}  // namespace eco
