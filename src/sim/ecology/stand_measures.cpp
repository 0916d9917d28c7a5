#include "sim/ecology/stand_measures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <tbb/parallel_for.h>

namespace eco {

double basalAreaOf(double dbh_m) {
  return std::numbers::pi / 4.0 * dbh_m * dbh_m;
}

void StandTally::add(double dbh_m, double height_m, double formFactor) {
  if (dbh_m < kMeasuredDbh_m) return;
  stems += 1.0;
  basalArea_m2 += basalAreaOf(dbh_m);
  diameterSquares_m2 += dbh_m * dbh_m;
  volume_m3 += formFactor * basalAreaOf(dbh_m) * height_m;
}

void StandTally::add(const StandTally& other) {
  stems += other.stems;
  basalArea_m2 += other.basalArea_m2;
  diameterSquares_m2 += other.diameterSquares_m2;
  volume_m3 += other.volume_m3;
}

StandMeasures StandTally::perHectare(double area_ha) const {
  StandMeasures m;
  if (area_ha <= 0.0 || stems <= 0.0) return m;
  m.stemsPerHa = stems / area_ha;
  m.basalArea_m2PerHa = basalArea_m2 / area_ha;
  m.volume_m3PerHa = volume_m3 / area_ha;
  m.qmd_cm = 100.0 * std::sqrt(diameterSquares_m2 / stems);
  m.sdi = m.stemsPerHa * std::pow(m.qmd_cm / kReinekeReference_cm, kReinekeSlope);
  return m;
}

std::vector<StandMeasures> measureStands(const Plants& p,
                                         const std::vector<EcosystemSpecies>& species,
                                         double area_ha) {
  const std::size_t all = species.size();
  const std::size_t groups = all + 1;  // each species, and all of them last
  // The dominant height's trees are looked for only in the height classes that hold them:
  // a landscape's 100 million plants are mostly seedlings, and a list of every height cost
  // gigabytes a year.
  constexpr float kHeightClass_m = 0.5f;
  constexpr int kHeightClasses = 256;  // the last holds every plant taller than 127.5 m
  auto classOf = [](float height_m) {
    return std::clamp(static_cast<int>(height_m / kHeightClass_m), 0, kHeightClasses - 1);
  };
  const std::size_t blocks = plantBlocks(p.size());
  // Each block's sums per group, in plant order; then the blocks' in block order.
  struct Part {
    StandTally tally;
    std::size_t plants = 0;
    double heightSum_m = 0.0;
    std::array<std::size_t, kHeightClasses> perClass{};
  };
  std::vector<std::vector<Part>> parts(blocks, std::vector<Part>(groups));
  std::vector<double> formFactor;
  for (const EcosystemSpecies& s : species) formFactor.push_back(s.ecology.life.formFactor);
  forEachPlantBlock(p.size(), [&](std::size_t b, std::size_t first, std::size_t end) {
    for (std::size_t i = first; i < end; ++i) {
      const std::size_t s = p.species[i];
      const int c = classOf(p.height_m[i]);
      for (const std::size_t group : {s, all}) {
        Part& part = parts[b][group];
        ++part.plants;
        part.heightSum_m += p.height_m[i];
        ++part.perClass[c];
        part.tally.add(p.dbh_m[i], p.height_m[i], formFactor[s]);
      }
    }
  });
  std::vector<StandMeasures> measures(groups);
  std::vector<std::array<std::size_t, kHeightClasses>> perClass(groups);
  for (std::size_t group = 0; group < groups; ++group) {
    StandTally tally;
    double heightSum_m = 0.0;
    std::size_t plants = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
      const Part& part = parts[b][group];
      tally.add(part.tally);
      heightSum_m += part.heightSum_m;
      plants += part.plants;
      for (int c = 0; c < kHeightClasses; ++c) perClass[group][c] += part.perClass[c];
    }
    measures[group] = tally.perHectare(area_ha);
    measures[group].plants = plants;
    measures[group].meanHeight_m = plants > 0 ? heightSum_m / static_cast<double>(plants) : 0.0;
  }
  // The 100 tallest per hectare (all of them on a smaller stand): the heights of each group's
  // plants in the classes that hold them, gathered block by block in plant order.
  std::vector<std::size_t> tallest(groups, 0);
  std::vector<int> lowest(groups, kHeightClasses);
  for (std::size_t group = 0; group < groups; ++group) {
    tallest[group] = std::min(measures[group].plants,
                              static_cast<std::size_t>(std::max(1.0, std::round(100.0 * area_ha))));
    if (tallest[group] == 0 || area_ha <= 0.0) continue;
    lowest[group] = kHeightClasses - 1;
    for (std::size_t above = perClass[group][lowest[group]]; above < tallest[group];)
      above += perClass[group][--lowest[group]];
  }
  std::vector<std::vector<std::vector<float>>> blockHeights(
      blocks, std::vector<std::vector<float>>(groups));
  forEachPlantBlock(p.size(), [&](std::size_t b, std::size_t first, std::size_t end) {
    for (std::size_t i = first; i < end; ++i) {
      const int c = classOf(p.height_m[i]);
      for (const std::size_t group : {static_cast<std::size_t>(p.species[i]), all})
        if (c >= lowest[group]) blockHeights[b][group].push_back(p.height_m[i]);
    }
  });
  tbb::parallel_for(std::size_t{0}, groups, [&](std::size_t group) {
    if (lowest[group] == kHeightClasses) return;
    std::vector<float> h;
    for (std::size_t b = 0; b < blocks; ++b)
      h.insert(h.end(), blockHeights[b][group].begin(), blockHeights[b][group].end());
    const std::size_t n = tallest[group];
    std::nth_element(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(n - 1), h.end(),
                     std::greater<>());
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k) sum += h[k];
    measures[group].dominantHeight_m = sum / static_cast<double>(n);
  });
  return measures;
}

double densestBlockBasalArea(const Plants& p, const Grid& g, double block_m) {
  const int bx = static_cast<int>(std::floor(g.width * g.dx_m / block_m));
  const int by = static_cast<int>(std::floor(g.height * g.dy_m / block_m));
  if (bx < 1 || by < 1) return 0.0;
  std::vector<double> area(static_cast<std::size_t>(bx) * by, 0.0);
  const double originEast = -0.5 * g.dx_m, originNorth = -0.5 * g.dy_m;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.dbh_m[i] < kMeasuredDbh_m) continue;
    const int x = static_cast<int>(std::floor((p.east_m[i] - originEast) / block_m));
    const int y = static_cast<int>(std::floor((p.north_m[i] - originNorth) / block_m));
    if (x < 0 || y < 0 || x >= bx || y >= by) continue;
    area[static_cast<std::size_t>(y) * bx + x] += basalAreaOf(p.dbh_m[i]);
  }
  return *std::max_element(area.begin(), area.end()) / (block_m * block_m / 1e4);
}

}  // namespace eco
