#include "render/scene/forest_floor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace eco {
namespace {

float linearFromSrgb(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

Field CanopyFloor::cover() const {
  Field share(crownsBelow.size());
  for (std::size_t c = 0; c < share.size(); ++c)
    share[c] = static_cast<float>(-std::expm1(-static_cast<double>(crownsBelow[c].back())));
  return share;
}

CanopyFloor canopyFloor(const Forest& forest, const TreeLibrary& library, const Grid& grid) {
  constexpr std::size_t kBands = kCanopyHeightTops_m.size();
  std::vector<std::array<double, kBands>> area(grid.cellCount(), std::array<double, kBands>{});
  std::vector<glm::dvec3> colour(grid.cellCount(), glm::dvec3(0.0));
  std::vector<glm::vec3> leafColors;
  for (const Species& s : library.species()) {
    const glm::vec3 c = s.appearance.leafColor;
    leafColors.emplace_back(linearFromSrgb(c.r), linearFromSrgb(c.g), linearFromSrgb(c.b));
  }
  for (std::size_t i = 0; i < forest.size(); ++i) {
    const int type = forest.type[i];
    const float radius = library.typeCrownRadius_m(type) * forest.scaleXZ[i];
    const double crown = std::numbers::pi * radius * radius * forest.presence[i];
    if (crown <= 0.0) continue;
    const float height = library.typeHeight_m(type) * forest.scaleY[i];
    const auto band = static_cast<std::size_t>(std::min<std::ptrdiff_t>(
        std::ranges::upper_bound(kCanopyHeightTops_m, height) - kCanopyHeightTops_m.begin(),
        kBands - 1));
    const glm::dvec3 leaves(leafColors[library.type(type).species] * forest.tint[i]);
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
    auto add = [&](std::size_t cell, double share) {
      area[cell][band] += share;
      colour[cell] += share * leaves;
    };
    forEachCovered([&](int, int) { ++covered; });
    if (covered > 0)
      forEachCovered([&](int x, int y) { add(grid.index(x, y), crown / covered); });
    else if (grid.contains(cx, cy))
      add(grid.index(cx, cy), crown);
  }
  const double cellArea = grid.dx_m * grid.dy_m;
  CanopyFloor floor;
  floor.crownsBelow.resize(grid.cellCount());
  floor.leafColor.resize(grid.cellCount());
  for (std::size_t c = 0; c < area.size(); ++c) {
    double below = 0.0;
    for (std::size_t b = 0; b < kBands; ++b) {
      below += area[c][b];
      floor.crownsBelow[c][b] = static_cast<float>(below / cellArea);
    }
    floor.leafColor[c] = below > 0.0 ? glm::vec3(colour[c] / below) : glm::vec3(0.0f);
  }
  return floor;
}

}  // namespace eco
