#include "sim/conditions/condition_maps.hpp"

#include <unistd.h>
#include <algorithm>
#include <cmath>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "sim/geotiff.hpp"
#include "sim/image_io.hpp"
#include "sim/plan/plan_spec.hpp"
#include "sim/run/run_format.hpp"

namespace eco {
namespace {

constexpr int kLegendHeight = 34;

struct Stop {
  float t;
  glm::vec3 color;
};

const std::vector<Stop>& rampFor(const std::string& field) {
  static const std::vector<Stop> altitude = {{0.0f, {0.16f, 0.36f, 0.18f}},
                                             {0.35f, {0.55f, 0.62f, 0.33f}},
                                             {0.7f, {0.55f, 0.42f, 0.30f}},
                                             {1.0f, {0.97f, 0.97f, 0.97f}}};
  static const std::vector<Stop> slope = {{0.0f, {0.27f, 0.0f, 0.33f}},
                                          {0.33f, {0.23f, 0.32f, 0.55f}},
                                          {0.66f, {0.13f, 0.66f, 0.52f}},
                                          {1.0f, {0.99f, 0.91f, 0.14f}}};
  static const std::vector<Stop> aspect = {{0.0f, {0.85f, 0.2f, 0.2f}},
                                           {0.25f, {0.85f, 0.8f, 0.2f}},
                                           {0.5f, {0.2f, 0.75f, 0.3f}},
                                           {0.75f, {0.2f, 0.4f, 0.85f}},
                                           {1.0f, {0.85f, 0.2f, 0.2f}}};
  static const std::vector<Stop> moisture = {
      {0.0f, {0.55f, 0.38f, 0.2f}}, {0.5f, {0.85f, 0.85f, 0.6f}}, {1.0f, {0.1f, 0.3f, 0.75f}}};
  static const std::vector<Stop> windiness = {{0.0f, {0.97f, 0.97f, 0.97f}},
                                              {1.0f, {0.35f, 0.1f, 0.5f}}};
  static const std::vector<Stop> sunniness = {
      {0.0f, {0.1f, 0.1f, 0.25f}}, {0.5f, {0.75f, 0.35f, 0.3f}}, {1.0f, {1.0f, 0.95f, 0.45f}}};
  static const std::vector<Stop> suitability = {
      {0.0f, {0.85f, 0.82f, 0.75f}}, {0.5f, {0.62f, 0.75f, 0.35f}}, {1.0f, {0.05f, 0.35f, 0.12f}}};
  static const std::vector<Stop> canopy = {
      {0.0f, {0.93f, 0.9f, 0.8f}}, {0.3f, {0.6f, 0.78f, 0.4f}}, {1.0f, {0.02f, 0.25f, 0.1f}}};
  // A plan's rules (sim/plan/management.hpp: 0 nothing, 1 seed source, 2 thinned, 3 planted,
  // 4 kept open), one colour each at its code.
  static const std::vector<Stop> plan = {{0.0f, {0.88f, 0.85f, 0.78f}},
                                         {0.25f, {0.1f, 0.38f, 0.2f}},
                                         {0.5f, {0.9f, 0.6f, 0.0f}},
                                         {0.75f, {0.0f, 0.62f, 0.45f}},
                                         {1.0f, {0.95f, 0.9f, 0.25f}}};
  if (field.starts_with("suitability")) return suitability;
  if (field == "plan") return plan;
  if (field == "canopy_height") return canopy;
  if (field == "altitude") return altitude;
  if (field == "slope") return slope;
  if (field == "aspect") return aspect;
  if (field == "moisture") return moisture;
  if (field == "windiness") return windiness;
  return sunniness;
}

// The map alone, one pixel per cell, so that its world file places it; cells outside the
// landscape (NaN) are transparent.
void writeMapPng(const std::filesystem::path& file, const Field& values, const Grid& grid,
                 const std::string& name, std::pair<double, double> range) {
  const auto [lo, hi] = range;
  const double span = hi > lo ? hi - lo : 1.0;
  Image image(grid.width, grid.height);
  for (int y = 0; y < grid.height; ++y)
    for (int x = 0; x < grid.width; ++x) {
      const float v = values[grid.index(x, y)];
      if (std::isnan(v)) continue;  // Image starts transparent
      const glm::vec3 c =
          (name == "aspect" && v < 0.0f) ? glm::vec3(0.5f) : rampColor(name, (v - lo) / span);
      image.set(x, y, glm::vec4(c, 1.0f));
    }
  writeRgba8Image(file, image);
}

// The legend beside the map: the ramp from its low to its high end, with their values and
// the unit; for the plan, a swatch and the name of each rule.
void writeLegendPng(const std::filesystem::path& file, const std::string& name,
                    const std::string& unit, std::pair<double, double> range) {
  const bool plan = name == "plan";
  const int kWidth = plan ? 480 : 256;
  const auto [lo, hi] = range;
  OIIO::ImageBuf image(OIIO::ImageSpec(kWidth, kLegendHeight, 3, OIIO::TypeDesc::UINT8));
  OIIO::ImageBufAlgo::fill(image, {0.12f, 0.12f, 0.12f});
  const float white[3] = {0.95f, 0.95f, 0.95f};
  // DejaVu Sans comes with Debian's fonts-dejavu-core (scripts/setup installs it); without
  // a font the legend keeps its bar and conditions.json holds the numbers.
  const char* font = "DejaVuSans";
  if (plan) {
    const int codes = static_cast<int>(std::size(kPlanMapCodeNames));
    for (int k = 0; k < codes; ++k) {
      const glm::vec3 c = rampColor(name, static_cast<double>(k) / (codes - 1));
      const int x0 = 4 + k * (kWidth / codes);
      OIIO::ImageBufAlgo::render_box(image, x0, 4, x0 + 24, 14, {c.r, c.g, c.b}, true);
      OIIO::ImageBufAlgo::render_text(image, x0, 29, kPlanMapCodeNames[k], 13, font, white);
    }
  } else {
    for (int y = 4; y < 14; ++y)
      for (int x = 4; x < kWidth - 4; ++x) {
        glm::vec3 c = rampColor(name, static_cast<double>(x - 4) / (kWidth - 9));
        float rgb[3] = {c.r, c.g, c.b};
        image.setpixel(x, y, rgb);
      }
    OIIO::ImageBufAlgo::render_text(image, 4, 29, fmt::format("{:.4g}", lo), 13, font, white);
    OIIO::ImageBufAlgo::render_text(
        image, kWidth - 4, 29,
        unit == "0-1" ? fmt::format("{:.4g}", hi) : fmt::format("{:.4g} {}", hi, unit), 13, font,
        white, OIIO::ImageBufAlgo::TextAlignX::Right);
  }
  image.geterror();  // a missing font is not an error worth failing the run for
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(kWidth) * kLegendHeight * 3);
  image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, rgb.data());
  writeRgb8Image(file, kWidth, kLegendHeight, rgb);
}

}  // namespace

std::pair<double, double> rampRange(const std::string& field, const std::string& unit,
                                    FieldStats stats) {
  if (unit == "0-1" || field.starts_with("suitability")) return {0.0, 1.0};
  if (field == "aspect") return {0.0, 360.0};
  if (field == "plan") return {0.0, 4.0};
  return {stats.min, stats.max};
}

glm::vec3 rampColor(const std::string& field, double t) {
  const std::vector<Stop>& stops = rampFor(field);
  float u = static_cast<float>(std::clamp(t, 0.0, 1.0));
  for (std::size_t i = 1; i < stops.size(); ++i)
    if (u <= stops[i].t)
      return glm::mix(stops[i - 1].color, stops[i].color,
                      (u - stops[i - 1].t) / (stops[i].t - stops[i - 1].t));
  return stops.back().color;
}

FieldStats writeFieldMap(const std::filesystem::path& folder, const std::string& name,
                         const std::string& unit, const Field& values, const Grid& grid) {
  FieldStats stats = statsOf(values);
  writeFloatImage(folder / (name + ".exr"), grid.width, grid.height, 1, values);
  writeGeoTiff(folder / (name + ".tif"), grid, values);
  const std::pair<double, double> range = rampRange(name, unit, stats);
  const std::filesystem::path png = folder / (name + ".png");
  writeMapPng(png, values, grid, name, range);
  writeImageGeoreference(png, grid);
  writeLegendPng(folder / (name + "_legend.png"), name, unit, range);
  return stats;
}

void writeConditionOutputs(const ConditionFields& fields, const ConditionsReport& report,
                           const Scenario& scenario, const std::filesystem::path& folder) {
  const RunPaths paths{folder};
  createOutputFolder(paths.mapsFolder());
  nlohmann::ordered_json json;
  json["scenario"] = scenario.name;
  json["grid"] = {{"width", fields.grid.width},
                  {"height", fields.grid.height},
                  {"cell_dx_m", fields.grid.dx_m},
                  {"cell_dy_m", fields.grid.dy_m},
                  // Map coordinates (0, 0) in the projected system; EPSG 0: local metres.
                  {"origin_east_m", fields.grid.originEast_m},
                  {"origin_north_m", fields.grid.originNorth_m},
                  {"epsg", fields.grid.epsg},
                  {"area_km2", fields.grid.area_m2() / 1e6}};
  for (const FieldInfo& info : conditionFieldInfo()) {
    const Field& values = fields.*info.field;
    FieldStats stats = writeFieldMap(paths.mapsFolder(), info.name, info.unit, values, fields.grid);
    nlohmann::ordered_json entry = {
        {"unit", info.unit}, {"min", stats.min}, {"mean", stats.mean}, {"max", stats.max}};
    for (const auto& [name, ms] : report.fieldMilliseconds)
      if (name == info.name) entry["ms"] = ms;
    json["fields"][info.name] = entry;
  }
  json["sun_rays"] = report.sunRays;
  json["sun_rays_per_second"] = report.sunRaysPerSecond;
  AtomicFile out(paths.conditionsJson());
  out.write(json.dump(2) + "\n");
  out.commit();
}

}  // namespace eco
