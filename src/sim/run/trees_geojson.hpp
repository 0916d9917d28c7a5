// A snapshot's trees as GeoJSON for GIS tools (QGIS, GDAL's ogrinfo): one Point feature per
// tree at its stem base in the terrain's projected coordinates (Grid's origin and EPSG
// code; local metres when the terrain has none), with its row of the trees CSV as
// properties. The coordinate system is named by the "crs" member of GeoJSON's 2008 form,
// which GDAL reads; RFC 7946 allows only longitude and latitude, which would need a
// projection library the program does without.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"
#include "sim/grid.hpp"
#include "sim/run/run_format.hpp"

namespace eco {

// Written a batch of trees at a time (a snapshot read in batches: `export` of a landscape's
// tens of millions), the features in the order they come.
class TreesGeoJsonWriter {
 public:
  TreesGeoJsonWriter(const std::filesystem::path& file, const Grid& grid, int year);
  // Rows whose species number `speciesNames`.
  void write(std::span<const TreeRow> rows, const std::vector<std::string>& speciesNames);
  void commit();

 private:
  AtomicFile out_;
  Grid grid_;
  std::vector<std::string> quotedNames_;
  std::size_t features_ = 0;
};

// A whole snapshot.
void writeTreesGeoJson(const std::filesystem::path& file, const TreeSnapshot& snapshot,
                       const Grid& grid);

}  // namespace eco
