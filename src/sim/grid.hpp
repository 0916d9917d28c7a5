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

  std::size_t cellCount() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  double area_m2() const { return dx_m * dy_m * static_cast<double>(cellCount()); }
};

using Field = std::vector<float>;

struct FieldStats {
  double min = 0.0, mean = 0.0, max = 0.0;
};
FieldStats statsOf(const Field& field);

}  // namespace eco
