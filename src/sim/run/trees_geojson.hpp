// A snapshot's trees as GeoJSON for GIS tools (QGIS, GDAL's ogrinfo): one Point feature per
// tree at its stem base in the terrain's projected coordinates (Grid's origin and EPSG
// code; local metres when the terrain has none), with its row of the trees CSV as
// properties. The coordinate system is named by the "crs" member of GeoJSON's 2008 form,
// which GDAL reads; RFC 7946 allows only longitude and latitude, which would need a
// projection library the program does without.
#pragma once

#include <filesystem>

#include "sim/grid.hpp"
#include "sim/run/run_format.hpp"

namespace eco {

void writeTreesGeoJson(const std::filesystem::path& file, const TreeSnapshot& snapshot,
                       const Grid& grid);

}  // namespace eco
