#include "sim/grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace eco {

FieldStats statsOf(const Field& field) {
  FieldStats s{std::numeric_limits<double>::max(), 0.0, std::numeric_limits<double>::lowest()};
  double sum = 0.0;
  std::size_t count = 0;
  for (float v : field) {
    if (!std::isfinite(v)) continue;
    s.min = std::min(s.min, static_cast<double>(v));
    s.max = std::max(s.max, static_cast<double>(v));
    sum += v;
    ++count;
  }
  if (count == 0) return {};
  s.mean = sum / static_cast<double>(count);
  return s;
}

float sampleBilinear(const Grid& grid, const Field& field, double east_m, double north_m) {
  // Continuous cell coordinates: x east from the west column, y south from the north row.
  const double fx = std::clamp(east_m / grid.dx_m, 0.0, static_cast<double>(grid.width - 1));
  const double fy = std::clamp((grid.height - 1) - north_m / grid.dy_m, 0.0,
                               static_cast<double>(grid.height - 1));
  const int x0 = std::min(static_cast<int>(fx), std::max(grid.width - 2, 0));
  const int y0 = std::min(static_cast<int>(fy), std::max(grid.height - 2, 0));
  const int x1 = std::min(x0 + 1, grid.width - 1), y1 = std::min(y0 + 1, grid.height - 1);
  const double tx = fx - x0, ty = fy - y0;
  const double north = (1.0 - tx) * field[grid.index(x0, y0)] + tx * field[grid.index(x1, y0)];
  const double south = (1.0 - tx) * field[grid.index(x0, y1)] + tx * field[grid.index(x1, y1)];
  return static_cast<float>((1.0 - ty) * north + ty * south);
}

}  // namespace eco
