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

CanopyFloorSum::CanopyFloorSum(const TreeLibrary& library, const Grid& grid)
    : library_(library),
      grid_(grid),
      area_(grid.cellCount(), std::array<double, kCanopyHeightTops_m.size()>{}),
      colour_(grid.cellCount(), glm::dvec3(0.0)) {
  for (const Species& s : library.species()) {
    const glm::vec3 c = s.appearance.leafColor;
    leafColors_.emplace_back(linearFromSrgb(c.r), linearFromSrgb(c.g), linearFromSrgb(c.b));
  }
}

void CanopyFloorSum::add(const Forest& forest) {
  constexpr std::size_t kBands = kCanopyHeightTops_m.size();
  const Grid& grid = grid_;
  for (std::size_t i = 0; i < forest.size(); ++i) {
    const int type = forest.type[i];
    const float radius = library_.typeCrownRadius_m(type) * forest.scaleXZ[i];
    const double crown = std::numbers::pi * radius * radius * forest.presence[i];
    if (crown <= 0.0) continue;
    const float height = library_.typeHeight_m(type) * forest.scaleY[i];
    const auto band = static_cast<std::size_t>(std::min<std::ptrdiff_t>(
        std::ranges::upper_bound(kCanopyHeightTops_m, height) - kCanopyHeightTops_m.begin(),
        kBands - 1));
    const glm::dvec3 leaves(leafColors_[library_.type(type).species] * forest.tint[i]);
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
      area_[cell][band] += share;
      colour_[cell] += share * leaves;
    };
    forEachCovered([&](int, int) { ++covered; });
    if (covered > 0)
      forEachCovered([&](int x, int y) { add(grid.index(x, y), crown / covered); });
    else if (grid.contains(cx, cy))
      add(grid.index(cx, cy), crown);
  }
}

CanopyFloor CanopyFloorSum::floor() const {
  const double cellArea = grid_.dx_m * grid_.dy_m;
  CanopyFloor floor;
  floor.crownsBelow.resize(area_.size());
  floor.leafColor.resize(area_.size());
  for (std::size_t c = 0; c < area_.size(); ++c) {
    double below = 0.0;
    for (std::size_t b = 0; b < kCanopyHeightTops_m.size(); ++b) {
      below += area_[c][b];
      floor.crownsBelow[c][b] = static_cast<float>(below / cellArea);
    }
    floor.leafColor[c] = below > 0.0 ? glm::vec3(colour_[c] / below) : glm::vec3(0.0f);
  }
  return floor;
}

CanopyFloor canopyFloor(const Forest& forest, const TreeLibrary& library, const Grid& grid) {
  CanopyFloorSum sum(library, grid);
  sum.add(forest);
  return sum.floor();
}

}  // namespace eco
