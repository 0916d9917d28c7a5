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

// moisture = P * (0.3 + 0.7 * T), P = 1 - exp(-precipitation / 800 mm),
// T = clamp((TWI - 4) / 12, 0, 1), and T = 1 in depressions (filled more than 1 cm: ponds
// and wetlands, where water stands).
void computeMoisture(const Terrain& terrain, const Field& slope_deg, double precipitation_mm,
                     Field& moisture);

}  // namespace eco
