// The five living conditions of the EcoMod paper (altitude, slope, moisture, windiness,
// sunniness) plus aspect, as parallel float arrays on the terrain's grid.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sim/conditions/sunlight.hpp"
#include "sim/scenario.hpp"
#include "sim/terrain.hpp"

namespace eco {

struct ConditionFields {
  Grid grid;
  Field altitude_m;
  Field slope_deg;
  Field aspect_deg;                // compass bearing faced, -1 where flat
  Field moisture;                  // the site's moisture number, Ellenberg's F scale 1..12
  Field windiness;                 // 0..1
  Field sunniness;                 // 0..1: 1 the sunniest slope of the latitude
  double openFlatSunniness = 1.0;  // sunniness of open, level ground

  // Light reaching the top of the canopy at a cell through the terrain, as a fraction of
  // what open level ground gets (above 1 on sunny slopes).
  double terrainLight(std::size_t cell) const { return sunniness[cell] / openFlatSunniness; }
};

// Name, unit and member of each field, in output order.
struct FieldInfo {
  const char* name;
  const char* unit;
  Field ConditionFields::*field;
};
const std::vector<FieldInfo>& conditionFieldInfo();

struct ConditionsReport {
  std::vector<std::pair<std::string, double>> fieldMilliseconds;
  std::uint64_t sunRays = 0;
  double sunRaysPerSecond = 0.0;
};

// The peak memory of computeConditions per terrain cell: `ecoforest conditions` on a
// generated 2049 x 2049 terrain peaks at 1.18 GB resident, 280 bytes a cell (the Embree
// scene of the terrain, the fields and their scratch arrays), rounded up.
inline constexpr std::uint64_t kConditionsBytesPerCell = 300;

// EnvironmentError, before anything is allocated, when the conditions of `grid` would not
// fit in the memory available (core/memory.hpp), unless `ignore` (--ignore-memory-check).
void requireMemoryForConditions(const Grid& grid, bool ignore);

// `progress(field, fraction)` is called as work advances (possibly from several threads).
ConditionFields computeConditions(const Terrain& terrain, const Climate& climate,
                                  const SunlightSettings& sunlight,
                                  ConditionsReport* report = nullptr,
                                  const std::function<void(const char*, double)>& progress = {});

}  // namespace eco
