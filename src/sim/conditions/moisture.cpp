#include "sim/conditions/moisture.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>

#include "core/angles.hpp"
#include "sim/conditions/slope.hpp"

namespace eco {
namespace {

constexpr int kNeighbours = 8;
constexpr int kDx[kNeighbours] = {-1, 0, 1, -1, 1, -1, 0, 1};
constexpr int kDy[kNeighbours] = {-1, -1, -1, 0, 0, 1, 1, 1};
constexpr double kEpsilon_m = 1e-5;      // the gradient priority-flood adds across filled ground
constexpr double kDepression_m = 0.01;   // filled deeper than this: a real depression
constexpr double kFlatSlope_deg = 0.01;  // level ground

// Whether filling raised the cell by more than kDepression_m: it lies in a closed depression.
bool inDepression(const Terrain& terrain, const std::vector<double>& filled, std::size_t cell) {
  return filled[cell] - terrain.height_m[cell] > kDepression_m;
}

}  // namespace

std::vector<double> fillDepressions(const Terrain& terrain) {
  const Grid& g = terrain.grid;
  std::vector<double> filled(terrain.height_m.begin(), terrain.height_m.end());
  std::vector<char> closed(g.cellCount(), 0);
  // (height, cell) pairs: the cell index breaks ties, so the fill is deterministic.
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x)
      if (x == 0 || y == 0 || x == g.width - 1 || y == g.height - 1) {
        closed[g.index(x, y)] = 1;
        open.push({filled[g.index(x, y)], g.index(x, y)});
      }
  while (!open.empty()) {
    auto [height, cell] = open.top();
    open.pop();
    const int x = static_cast<int>(cell % g.width), y = static_cast<int>(cell / g.width);
    for (int k = 0; k < kNeighbours; ++k) {
      const int nx = x + kDx[k], ny = y + kDy[k];
      if (!g.contains(nx, ny) || closed[g.index(nx, ny)]) continue;
      const std::size_t n = g.index(nx, ny);
      closed[n] = 1;
      filled[n] = std::max(filled[n], height + kEpsilon_m);
      open.push({filled[n], n});
    }
  }
  return filled;
}

Field flowAccumulation(const Terrain& terrain, const std::vector<double>& filled,
                       const Field& slope_deg) {
  const Grid& g = terrain.grid;
  const double diagonal = std::hypot(g.dx_m, g.dy_m);
  std::vector<std::int64_t> receiver(g.cellCount(), -1);
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const std::size_t c = g.index(x, y);
      // A natural flat keeps its water; a depression's floor passes it on to the spill point.
      if (!inDepression(terrain, filled, c) && slope_deg[c] < kFlatSlope_deg) continue;
      double steepest = 0.0;
      for (int k = 0; k < kNeighbours; ++k) {
        const int nx = x + kDx[k], ny = y + kDy[k];
        if (!g.contains(nx, ny)) continue;
        const double distance = kDx[k] == 0 ? g.dy_m : kDy[k] == 0 ? g.dx_m : diagonal;
        const double drop = (filled[c] - filled[g.index(nx, ny)]) / distance;
        if (drop > steepest)
          steepest = drop, receiver[c] = static_cast<std::int64_t>(g.index(nx, ny));
      }
    }
  // Highest cells first, so each passes on everything it has gathered.
  std::vector<std::size_t> order(g.cellCount());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return filled[a] != filled[b] ? filled[a] > filled[b] : a < b;
  });
  Field accumulation(g.cellCount(), 1.0f);
  for (std::size_t c : order)
    if (receiver[c] >= 0) accumulation[static_cast<std::size_t>(receiver[c])] += accumulation[c];
  return accumulation;
}

Field wetnessIndex(const Terrain& terrain, const Field& accumulation, const Field& slope_deg) {
  const Grid& g = terrain.grid;
  const double cellArea = g.dx_m * g.dy_m, cellWidth = std::sqrt(cellArea);
  const double minTan = std::tan(radians(0.1));
  Field twi(g.cellCount());
  for (std::size_t c = 0; c < twi.size(); ++c) {
    double a = accumulation[c] * cellArea / cellWidth;
    double tanBeta = std::max(std::tan(radians(static_cast<double>(slope_deg[c]))), minTan);
    twi[c] = static_cast<float>(std::log(a / tanBeta));
  }
  return twi;
}

double climateMoisture(double precipitation_mm) {
  return kMoistureAt1100mm + (precipitation_mm - 1100.0) / kPrecipitationPerUnit_mm;
}

void computeMoisture(const Terrain& terrain, const Field& slope_deg, double precipitation_mm,
                     Field& moisture) {
  const std::vector<double> filled = fillDepressions(terrain);
  Field twi = wetnessIndex(terrain, flowAccumulation(terrain, filled, slope_deg), slope_deg);
  const double climate = climateMoisture(precipitation_mm);
  moisture.resize(twi.size());
  for (std::size_t c = 0; c < twi.size(); ++c) {
    double f = climate + kMoisturePerWetness * (twi[c] - kReferenceWetness);
    // Standing water: a pond deeper than a centimetre is at least wet (F 9).
    if (terrain.closedDepressions == ClosedDepressions::Pond && inDepression(terrain, filled, c))
      f = std::max(f, kPondMoisture);
    moisture[c] = static_cast<float>(std::clamp(f, kDriestMoisture, kWettestMoisture));
  }
}

Field moistureOf(const Terrain& terrain, double precipitation_mm) {
  Field slope_deg, aspect_deg, moisture;
  computeSlopeAspect(terrain, slope_deg, aspect_deg);
  computeMoisture(terrain, slope_deg, precipitation_mm, moisture);
  return moisture;
}

}  // namespace eco
