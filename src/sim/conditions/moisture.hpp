// Soil moisture from the terrain's hydrology and the climate (docs/conditions.md):
// priority-flood pit filling (Barnes et al. 2014, with an epsilon gradient), D8 flow
// accumulation, the topographic wetness index TWI = ln(a / tan beta), and precipitation.
#pragma once

#include <vector>

#include "sim/terrain.hpp"

namespace eco {

// Heights with every depression filled to its spill level, plus a tiny epsilon gradient
// so that every cell has a downhill path to the map edge.
std::vector<double> fillDepressions(const Terrain& terrain);

// Number of cells draining through each cell (itself included). Water follows the steepest
// descent (D8) of the filled surface; natural flats -- level, unfilled ground such as a
// plain or a level valley floor -- keep what reaches them instead of draining it along an
// arbitrary epsilon gradient.
Field flowAccumulation(const Terrain& terrain, const std::vector<double>& filled,
                       const Field& slope_deg);

// ln(a / tan beta): a is the specific catchment area (accumulated cells x cell area / cell
// width), beta the slope, at least 0.1 degree.
Field wetnessIndex(const Terrain& terrain, const Field& accumulation, const Field& slope_deg);

// The site's moisture number on Ellenberg's F scale (1 extremely dry .. 12 under water; ours,
// docs/conditions.md): the climate's number, F = 5 (fresh) at 1100 mm and one unit per
// 400 mm more or less, plus a quarter unit per unit of TWI above the reference wetness 6 of
// an open mid-slope (100 m below its ridge at 15 degrees: ln(100 / 0.27) = 5.9), and at least
// F = 9 (wet) in closed depressions when the terrain's are ponds; drained ones gather their
// catchment's water and are as moist as their TWI says. A quarter unit spreads the TWI of hill
// country (about 3 on ridges to 15 on valley floors) over the three units of F its woods span, from
// the dry ridges' F 4 to the moist valleys' F 7. Continuous: only the scale's ends clamp it.
inline constexpr double kMoistureAt1100mm = 5.0, kPrecipitationPerUnit_mm = 400.0;
inline constexpr double kMoisturePerWetness = 0.25, kReferenceWetness = 6.0;
inline constexpr double kPondMoisture = 9.0, kDriestMoisture = 1.0, kWettestMoisture = 12.0;
// Fresh ground (F 5): what the renderer assumes where it is given no moisture.
inline constexpr float kFreshMoisture = 5.0f;
double climateMoisture(double precipitation_mm);
void computeMoisture(const Terrain& terrain, const Field& slope_deg, double precipitation_mm,
                     Field& moisture);
// The same from the terrain alone (its slope computed here): for those that need no other
// condition, such as the renderer's ground cover.
Field moistureOf(const Terrain& terrain, double precipitation_mm);

}  // namespace eco
