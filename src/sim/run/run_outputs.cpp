#include "sim/run/run_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace eco {
namespace {

// Calls f(cell) for every cell whose centre lies inside the crown of plant i.
template <typename F>
void forCellsUnderCrown(const Grid& g, const Plants& p, std::size_t i, F&& f) {
  const double r = p.crownRadius_m[i];
  const double east = p.east_m[i], north = p.north_m[i];
  const int x0 = std::max(0, static_cast<int>(std::ceil((east - r) / g.dx_m)));
  const int x1 = std::min(g.width - 1, static_cast<int>(std::floor((east + r) / g.dx_m)));
  // Rows count from the north edge: north = (height - 1 - y) dy.
  const int y0 = std::max(0, static_cast<int>(std::ceil((g.height - 1) - (north + r) / g.dy_m)));
  const int y1 =
      std::min(g.height - 1, static_cast<int>(std::floor((g.height - 1) - (north - r) / g.dy_m)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double de = g.eastOf(x) - east, dn = g.northOf(y) - north;
      if (de * de + dn * dn <= r * r) f(g.index(x, y));
    }
}

}  // namespace

std::vector<StatsRow> statsOfYear(const Ecosystem& ecosystem) {
  const Plants& p = ecosystem.plants();
  const Grid& g = ecosystem.grid();
  const std::size_t speciesCount = ecosystem.species().size();
  std::vector<StatsRow> rows(speciesCount);
  std::vector<double> heightSum(speciesCount, 0.0);
  std::vector<std::vector<std::uint8_t>> covered(speciesCount,
                                                 std::vector<std::uint8_t>(g.cellCount(), 0));
  for (std::size_t i = 0; i < p.size(); ++i) {
    StatsRow& row = rows[p.species[i]];
    ++row.alive;
    heightSum[p.species[i]] += p.height_m[i];
    row.basalArea_m2PerHa += std::numbers::pi / 4.0 * p.dbh_m[i] * p.dbh_m[i];
    forCellsUnderCrown(g, p, i, [&](std::size_t cell) { covered[p.species[i]][cell] = 1; });
  }
  const double area_ha = g.area_m2() / 1e4;
  for (std::size_t s = 0; s < speciesCount; ++s) {
    StatsRow& row = rows[s];
    row.year = ecosystem.year();
    row.species = static_cast<std::int32_t>(s);
    row.born = ecosystem.bornLastYear()[s];
    row.died = ecosystem.diedLastYear()[s];
    row.meanHeight_m = row.alive ? heightSum[s] / row.alive : 0.0;
    row.basalArea_m2PerHa /= area_ha;
    row.coverFraction = static_cast<double>(std::count(covered[s].begin(), covered[s].end(), 1)) /
                        static_cast<double>(g.cellCount());
  }
  return rows;
}

Field canopyHeight(const Ecosystem& ecosystem) {
  const Plants& p = ecosystem.plants();
  Field height(ecosystem.grid().cellCount(), 0.0f);
  for (std::size_t i = 0; i < p.size(); ++i)
    forCellsUnderCrown(ecosystem.grid(), p, i, [&](std::size_t cell) {
      height[cell] = std::max(height[cell], p.height_m[i]);
    });
  return height;
}

}  // namespace eco
