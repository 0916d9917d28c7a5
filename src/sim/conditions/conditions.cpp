#include "sim/conditions/conditions.hpp"

#include <chrono>

#include <fmt/format.h>

#include "core/memory.hpp"
#include "core/stopwatch.hpp"
#include "sim/conditions/moisture.hpp"
#include "sim/conditions/slope.hpp"
#include "sim/conditions/windiness.hpp"

namespace eco {

const std::vector<FieldInfo>& conditionFieldInfo() {
  static const std::vector<FieldInfo> info = {
      {"altitude", "m", &ConditionFields::altitude_m},
      {"slope", "degrees", &ConditionFields::slope_deg},
      {"aspect", "degrees", &ConditionFields::aspect_deg},
      {"moisture", "Ellenberg F", &ConditionFields::moisture},
      {"windiness", "0-1", &ConditionFields::windiness},
      {"sunniness", "0-1", &ConditionFields::sunniness},
  };
  return info;
}

ConditionFields computeConditions(const Terrain& terrain, const Climate& climate,
                                  const SunlightSettings& sunlight, ConditionsReport* report,
                                  const std::function<void(const char*, double)>& progress) {
  using Clock = std::chrono::steady_clock;
  ConditionFields fields;
  fields.grid = terrain.grid;
  auto timed = [&](const char* name, auto&& work) {
    if (progress) progress(name, 0.0);
    auto start = Clock::now();
    work();
    double ms = millisecondsSince(start);
    if (report) report->fieldMilliseconds.emplace_back(name, ms);
    if (progress) progress(name, 1.0);
    return ms;
  };
  timed("altitude", [&] { fields.altitude_m = terrain.height_m; });
  timed("slope", [&] { computeSlopeAspect(terrain, fields.slope_deg, fields.aspect_deg); });
  timed("moisture", [&] {
    computeMoisture(terrain, fields.slope_deg, climate.annualPrecipitation_mm, fields.moisture);
  });
  timed("windiness",
        [&] { computeWindiness(terrain, climate.prevailingWindFrom_deg, fields.windiness); });
  SunlightParts parts;
  double sunMs = timed("sunniness", [&] {
    computeSunniness(terrain, fields.slope_deg, fields.aspect_deg, climate.latitude_deg, sunlight,
                     fields.sunniness, &parts, [&](double f) {
                       if (progress) progress("sunniness", f);
                     });
  });
  fields.openFlatSunniness = 1.0 / parts.best;
  // Outside the landscape (a GeoTIFF's no-data) there are no conditions.
  for (const FieldInfo& info : conditionFieldInfo())
    fields.*info.field = maskOutside(terrain, std::move(fields.*info.field));
  if (report) {
    report->sunRays = parts.rays;
    report->sunRaysPerSecond = sunMs > 0.0 ? parts.rays / (sunMs / 1000.0) : 0.0;
  }
  return fields;
}

void requireMemoryForConditions(const Grid& grid, bool ignore) {
  requireMemory(grid.cellCount() * kConditionsBytesPerCell,
                fmt::format("the living conditions of a {} x {} terrain", grid.width, grid.height),
                "Use a smaller or coarser terrain, or --ignore-memory-check to go ahead anyway",
                ignore);
}

}  // namespace eco
