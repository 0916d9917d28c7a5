#include "sim/run/run_outputs.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include "sim/ecology/stand_measures.hpp"

namespace eco {
namespace {

// Calls f(cell) for every cell whose centre lies inside the crown of plant i. Every plant,
// every year, and most are seedlings whose crown holds no cell's centre: the columns are
// looked at first, with the cells' widths' inverses, before any row.
template <typename F>
void forCellsUnderCrown(const Grid& g, const Plants& p, std::size_t i, F&& f) {
  const double r = p.crownRadius_m[i];
  const double east = p.east_m[i], north = p.north_m[i];
  const double perDx = 1.0 / g.dx_m, perDy = 1.0 / g.dy_m;
  const int x0 = std::max(0, static_cast<int>(std::ceil((east - r) * perDx)));
  const int x1 = std::min(g.width - 1, static_cast<int>(std::floor((east + r) * perDx)));
  if (x0 > x1) return;
  // Rows count from the north edge: north = (height - 1 - y) dy.
  const int y0 = std::max(0, static_cast<int>(std::ceil((g.height - 1) - (north + r) * perDy)));
  const int y1 =
      std::min(g.height - 1, static_cast<int>(std::floor((g.height - 1) - (north - r) * perDy)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double de = g.eastOf(x) - east, dn = g.northOf(y) - north;
      if (de * de + dn * dn <= r * r) f(g.index(x, y));
    }
}

}  // namespace

std::vector<StatsRow> statsOfYear(const Ecosystem& ecosystem, const PlanYear& plan) {
  const Plants& p = ecosystem.plants();
  const Grid& g = ecosystem.grid();
  const auto speciesCount = static_cast<int>(ecosystem.species().size());
  const double area_ha = g.area_m2() / 1e4;
  std::vector<StatsRow> rows(static_cast<std::size_t>(speciesCount) + 1);
  std::vector<std::vector<std::uint8_t>> covered(static_cast<std::size_t>(speciesCount));
  std::vector<StandMeasures> measures;
  double densest_m2PerHa = 0.0;
  for (std::vector<std::uint8_t>& cells : covered) cells.assign(g.cellCount(), 0);
  // The crowns, the forester's measures (with the counts and heights) and the densest
  // hectare are independent: they run side by side. The sums do not depend on the thread
  // count (measureStands, densestBlockBasalArea); the crowns are stamped side by side (a cell
  // that several crowns cover is set by each). Only the species' crowns are stamped: the
  // stand covers the cells some species covers.
  tbb::parallel_invoke(
      [&] {
        tbb::parallel_for(std::size_t{0}, p.size(), [&](std::size_t i) {
          std::vector<std::uint8_t>& cells = covered[p.species[i]];
          forCellsUnderCrown(g, p, i, [&](std::size_t cell) {
            std::atomic_ref<std::uint8_t>(cells[cell]).store(1, std::memory_order_relaxed);
          });
        });
      },
      [&] { measures = measureStands(p, ecosystem.species(), area_ha); },
      [&] { densest_m2PerHa = densestBlockBasalArea(p, g); });
  std::vector<std::size_t> coveredCells(rows.size(), 0);
  for (std::size_t cell = 0; cell < g.cellCount(); ++cell) {
    bool any = false;
    for (std::size_t r = 0; r < covered.size(); ++r) {
      coveredCells[r] += covered[r][cell];
      any = any || covered[r][cell];
    }
    coveredCells.back() += any ? 1 : 0;
  }
  for (std::size_t r = 0; r < rows.size(); ++r) {
    StatsRow& row = rows[r];
    const bool stand = r + 1 == rows.size();
    row.year = ecosystem.year();
    row.species = stand ? kAllSpecies : static_cast<std::int32_t>(r);
    for (int s = 0; s < speciesCount; ++s)
      if (stand || s == static_cast<int>(r)) {
        row.born += ecosystem.bornLastYear()[s];
        row.died += ecosystem.diedLastYear()[s];
        row.diedAfterPlanting += ecosystem.plantedDiedLastYear()[s];
        row.planted += plan.planted[s];
        row.removed += plan.removed[s];
        row.removedVolume_m3PerHa += plan.removedVolume_m3[s] / area_ha;
      }
    const StandMeasures& m = measures[r];
    row.alive = static_cast<std::int64_t>(m.plants);
    row.meanHeight_m = m.meanHeight_m;
    row.stemsPerHa = m.stemsPerHa;
    row.basalArea_m2PerHa = m.basalArea_m2PerHa;
    row.qmd_cm = m.qmd_cm;
    row.dominantHeight_m = m.dominantHeight_m;
    row.sdi = m.sdi;
    row.volume_m3PerHa = m.volume_m3PerHa;
    row.coverFraction = static_cast<double>(coveredCells[r]) / static_cast<double>(g.cellCount());
    if (stand) row.densestHectareBasalArea_m2PerHa = densest_m2PerHa;
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
