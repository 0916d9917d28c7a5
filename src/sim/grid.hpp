// The raster every condition field shares: width x height cells, row 0 at the north edge,
// x growing east. Fields are flat float arrays indexed by y * width + x.
#pragma once

#include <cstddef>
#include <vector>

namespace eco {

struct Grid {
  int width = 0;
  int height = 0;
  double dx_m = 1.0;  // ground distance between cell centres, east-west
  double dy_m = 1.0;  // and north-south
  // Where the map lies in a projected coordinate system, when its heightmap said so (a
  // GeoTIFF, geotiff.hpp): the coordinates of map point (0, 0), the centre of the south-west
  // cell, and the system's EPSG code. Without one (epsg 0) map coordinates are local metres.
  double originEast_m = 0.0, originNorth_m = 0.0;
  int epsg = 0;

  std::size_t cellCount() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  double area_m2() const { return dx_m * dy_m * static_cast<double>(cellCount()); }

  // Map coordinates of plants: metres east of the westmost cell centres and north of the
  // southmost ones; cell (x, y) covers the square of side dx, dy around its centre.
  double eastOf(int x) const { return x * dx_m; }
  double northOf(int y) const { return (height - 1 - y) * dy_m; }
  // The cell holding a map position, or -1 outside the grid.
  long cellAt(double east_m, double north_m) const {
    const int x = columnAt(east_m), y = rowAt(north_m);
    return x < 0 || y < 0 ? -1 : static_cast<long>(index(x, y));
  }
  // The column holding an east and the row holding a north, or -1 outside the grid.
  int columnAt(double east_m) const {
    const double fx = east_m / dx_m + 0.5;
    return fx >= 0.0 && fx < width ? static_cast<int>(fx) : -1;
  }
  int rowAt(double north_m) const {
    const double fy = (height - 1) + 0.5 - north_m / dy_m;
    return fy >= 0.0 && fy < height ? static_cast<int>(fy) : -1;
  }
};

using Field = std::vector<float>;

struct FieldStats {
  double min = 0.0, mean = 0.0, max = 0.0;
};
// Over the finite values (NaN marks cells outside the landscape); all zero when none is.
FieldStats statsOf(const Field& field);

// A field's value at a map position, interpolated bilinearly between the four nearest cell
// centres; positions beyond the outer centres take the edge's values.
float sampleBilinear(const Grid& grid, const Field& field, double east_m, double north_m);

}  // namespace eco
