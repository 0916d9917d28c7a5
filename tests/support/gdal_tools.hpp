// GDAL's command-line tools as test-only clients (the program itself is GDAL-free):
// georeferencing a test raster the way a GIS would, and reading back what ecoforest wrote.
// scripts/test installs gdal-bin; tests skip with a message where it is missing.
#pragma once

#include <filesystem>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_files.hpp"

namespace eco::test {

inline bool gdalInstalled() {
  return runCommand("command -v gdal_translate").exitCode == 0;
}

// A GeoTIFF made by GDAL from a plain one-band TIFF: pixels of `pixel_m` whose outer
// north-west corner is at (west, north) in EPSG `epsg`, with `noData` declared.
inline void gdalGeoreference(const std::filesystem::path& raw, const std::filesystem::path& out,
                             int epsg, double west, double north, double pixel_m, int width,
                             int height, double noData) {
  const CommandResult r = runCommand(fmt::format(
      "gdal_translate -q -of GTiff -a_srs EPSG:{} -a_ullr {} {} {} {} -a_nodata {} {} {}", epsg,
      west, north, west + width * pixel_m, north - height * pixel_m, noData, raw.string(),
      out.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
}

// `gdalinfo -json` of a raster.
inline nlohmann::json gdalInfo(const std::filesystem::path& file) {
  const CommandResult r = runCommand("gdalinfo -json " + file.string() + " 2>/dev/null");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return r.exitCode == 0 ? nlohmann::json::parse(r.output) : nlohmann::json{};
}

// The EPSG code of a raster's coordinate system as GDAL reads it (0 if none).
inline int gdalEpsg(const nlohmann::json& info) {
  if (!info.contains("stac") || !info["stac"].contains("proj:epsg") ||
      info["stac"]["proj:epsg"].is_null())
    return 0;
  return info["stac"]["proj:epsg"].get<int>();
}

}  // namespace eco::test
