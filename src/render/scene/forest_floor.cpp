#include "render/scene/forest_floor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace eco {

Field canopyCover(const Forest& forest, const TreeLibrary& library, const Grid& grid) {
  std::vector<double> area(grid.cellCount(), 0.0);
  for (std::size_t i = 0; i < forest.size(); ++i) {
    const float radius = library.typeCrownRadius_m(forest.type[i]) * forest.scaleXZ[i];
    const double crown = std::numbers::pi * radius * radius * forest.presence[i];
    if (crown <= 0.0) continue;
    // Map east and north of the stem (world x east, z south), and its cell.
    const double east = forest.position[i].x, north = -forest.position[i].z;
    const int cx = static_cast<int>(std::lround(east / grid.dx_m));
    const int cy = grid.height - 1 - static_cast<int>(std::lround(north / grid.dy_m));
    const int reachX = static_cast<int>(radius / grid.dx_m) + 1;
    const int reachY = static_cast<int>(radius / grid.dy_m) + 1;
    // The cells whose centres the disc covers, counted first so each gets an equal share.
    int covered = 0;
    auto forEachCovered = [&](auto&& visit) {
      for (int y = cy - reachY; y <= cy + reachY; ++y)
        for (int x = cx - reachX; x <= cx + reachX; ++x) {
          if (!grid.contains(x, y)) continue;
          const double de = grid.eastOf(x) - east, dn = grid.northOf(y) - north;
          if (de * de + dn * dn <= static_cast<double>(radius) * radius) visit(x, y);
        }
    };
    forEachCovered([&](int, int) { ++covered; });
    if (covered > 0)
      forEachCovered([&](int x, int y) { area[grid.index(x, y)] += crown / covered; });
    else if (grid.contains(cx, cy))
      area[grid.index(cx, cy)] += crown;
  }
  const double cellArea = grid.dx_m * grid.dy_m;
  Field cover(grid.cellCount());
  for (std::size_t c = 0; c < cover.size(); ++c)
    cover[c] = static_cast<float>(1.0 - std::exp(-area[c] / cellArea));
  return cover;
}

}  // namespace eco
