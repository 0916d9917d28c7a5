// Exposure to the prevailing wind (docs/conditions.md), on an absolute scale that does not
// depend on the map's own relief: Winstral et al.'s (2002) upwind maximum slope Sx -- the
// steepest angle up to the terrain upwind within a search distance, averaged over three
// directions across a 30-degree sector -- and the topographic position, the angle a cell
// rises above the mean ground around it. Sx > 0 means higher ground upwind: a lee,
// sheltered cell; Sx < 0 an exposed one.
#pragma once

#include "sim/terrain.hpp"

namespace eco {

inline constexpr double kWindSearch_m = 500.0;  // how far upwind Sx looks

// Winstral's Sx in degrees for every cell; `from_deg` is the compass bearing the wind comes from.
Field upwindSlope(const Terrain& terrain, double from_deg, double searchDistance_m = kWindSearch_m);

// The angle in degrees at which each cell rises above the mean height of the square of
// half-side `radius_m` around it (negative in hollows).
Field elevationAngle(const Terrain& terrain, double radius_m);

// windiness = clamp(0.3 + (position angle - Sx) / 30 deg, 0, 1): open level ground is 0.3
// whatever its size, a lee lower, an exposed ridge higher (ours, docs/conditions.md).
inline constexpr double kPositionRadius_m = 500.0;
inline constexpr double kOpenGroundWindiness = 0.3, kExposureScale_deg = 30.0;
void computeWindiness(const Terrain& terrain, double from_deg, Field& windiness);

}  // namespace eco
