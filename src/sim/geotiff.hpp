// Georeferenced rasters, GDAL-free: a GeoTIFF's tags read and written with libgeotiff and
// libtiff, the libraries made for them (OpenImageIO, which reads the pixels, shows none of
// these tags). What is read: the pixel scale, the tie point, the raster type (pixel is area
// or point), the projected coordinate system's EPSG code (its GeoKeys) and the no-data
// value (the GDAL_NODATA tag GDAL and QGIS write). Map coordinates are metres in a
// projected system, so a geographic system (degrees) or a unit other than the metre is
// refused.
#pragma once

#include <filesystem>
#include <optional>

#include "sim/grid.hpp"

namespace eco {

struct GeoTiffTags {
  bool georeferenced = false;  // a pixel scale and a tie point
  double pixelWidth_m = 0.0, pixelHeight_m = 0.0;
  // The projected coordinates of the outer north-west corner of pixel (0, 0).
  double westEdge_m = 0.0, northEdge_m = 0.0;
  int epsg = 0;  // 0: not given (or user-defined)
  std::optional<double> noData;
};

// The tags of a TIFF file; a file without any is not georeferenced. An InputError names the
// file when it is not a TIFF, or its system is geographic or not in metres.
GeoTiffTags readGeoTiffTags(const std::filesystem::path& file);

// The grid placed by the tags: the file's pixel size (dx, dy) and the origin and EPSG code
// of Grid's map coordinates.
void placeGrid(const GeoTiffTags& tags, Grid& grid);

// A one-band 32-bit float GeoTIFF of `values` on the grid: its origin, cell size and EPSG
// code, and NaN as the no-data value (GDAL_NODATA "nan"); atomically.
void writeGeoTiff(const std::filesystem::path& file, const Grid& grid, const Field& values);

// What places an image that holds no tags itself (a PNG) in a GIS: its world file (.pgw
// beside a .png), the cell size and the centre of the north-west cell, and with a known
// EPSG code an IMAGE.aux.xml naming the coordinate system (GDAL's auxiliary metadata).
void writeImageGeoreference(const std::filesystem::path& image, const Grid& grid);

}  // namespace eco
