// What `ecoforest conditions` writes: maps/<field>.exr (raw floats), maps/<field>.tif (the
// same floats as a georeferenced GeoTIFF), maps/<field>.png (colour-mapped, one pixel per
// cell, placed by its world file <field>.pgw and, with a known coordinate system,
// <field>.png.aux.xml), maps/<field>_legend.png (the colour ramp with
// its range and unit) and conditions.json.
#pragma once

#include <filesystem>
#include <string>
#include <utility>

#include "sim/conditions/conditions.hpp"

namespace eco {

// RGB of a field value on the field's colour ramp; t in [0, 1].
glm::vec3 rampColor(const std::string& field, double t);
// The values a map's ramp spans: fixed for bounded fields (aspect 0-360, unit "0-1", the
// plan's codes 0-4, whose colours stand for its rules), the data's least and greatest
// otherwise. Maps and the terrain overlay colour alike by it.
std::pair<double, double> rampRange(const std::string& field, const std::string& unit,
                                    FieldStats stats);

// One map: <folder>/<name>.exr, .tif, .png with .pgw, and _legend.png. Names pick the colour ramp
// (a condition's, "suitability_*", "canopy_height" or "plan"); unit "0-1" fixes the range to
// [0, 1].
FieldStats writeFieldMap(const std::filesystem::path& folder, const std::string& name,
                         const std::string& unit, const Field& values, const Grid& grid);

void writeConditionOutputs(const ConditionFields& fields, const ConditionsReport& report,
                           const Scenario& scenario, const std::filesystem::path& folder);

}  // namespace eco
