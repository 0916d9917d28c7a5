#include "sim/ecology/light_grid.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>

#include <tbb/parallel_for.h>

#include "core/error.hpp"

namespace eco {
namespace {

constexpr double kColumnArea_m2 = kLightColumn_m * kLightColumn_m;
// A crown's projection is sampled on this many points per column side to share it out.
constexpr int kSamples = 4;

double crownArea(const CrownShape& crown) {
  return std::numbers::pi * crown.radius_m * crown.radius_m;
}

// The share of light a crown's leaves take from what reaches them.
double absorbedShare(const CrownShape& crown) {
  const double area = crownArea(crown);
  if (area <= 0.0) return 0.0;
  return 1.0 - std::exp(-kLeafExtinction * crown.leafArea_m2 / area);
}

}  // namespace

LightGrid::LightGrid(const Grid& terrain, const Field& topLight)
    : columnsX_(
          std::max(1, static_cast<int>(std::ceil(terrain.width * terrain.dx_m / kLightColumn_m)))),
      columnsY_(
          std::max(1, static_cast<int>(std::ceil(terrain.height * terrain.dy_m / kLightColumn_m)))),
      originEast_m_(-0.5 * terrain.dx_m),
      originNorth_m_(-0.5 * terrain.dy_m) {
  ECO_ASSERT(topLight.size() == terrain.cellCount(),
             "top light " << topLight.size() << " for " << terrain.cellCount() << " cells");
  topLight_.resize(static_cast<std::size_t>(columnsX_) * columnsY_);
  for (int y = 0; y < columnsY_; ++y)
    for (int x = 0; x < columnsX_; ++x) {
      // The terrain cell under the column's centre.
      const double east = originEast_m_ + (x + 0.5) * kLightColumn_m;
      const double north = originNorth_m_ + (y + 0.5) * kLightColumn_m;
      const int cx =
          std::clamp(static_cast<int>(std::lround(east / terrain.dx_m)), 0, terrain.width - 1);
      const int cy =
          std::clamp(terrain.height - 1 - static_cast<int>(std::lround(north / terrain.dy_m)), 0,
                     terrain.height - 1);
      topLight_[static_cast<std::size_t>(y) * columnsX_ + x] = topLight[terrain.index(cx, cy)];
    }
  columnStart_.assign(topLight_.size() + 1, 0);
}

void LightGrid::footprint(const CrownShape& crown, std::vector<Footprint>& out) const {
  out.clear();
  if (!(crown.leafArea_m2 > 0.0f)) return;
  const double r = crown.radius_m;
  if (r <= 0.5 * kLightColumn_m) {
    out.push_back({static_cast<std::int32_t>(columnAt(crown.east_m, crown.north_m)), 1.0f});
    return;
  }
  const int x0 = static_cast<int>(std::floor((crown.east_m - r - originEast_m_) / kLightColumn_m));
  const int x1 = static_cast<int>(std::floor((crown.east_m + r - originEast_m_) / kLightColumn_m));
  const int y0 =
      static_cast<int>(std::floor((crown.north_m - r - originNorth_m_) / kLightColumn_m));
  const int y1 =
      static_cast<int>(std::floor((crown.north_m + r - originNorth_m_) / kLightColumn_m));
  int total = 0;
  for (int y = std::max(y0, 0); y <= std::min(y1, columnsY_ - 1); ++y)
    for (int x = std::max(x0, 0); x <= std::min(x1, columnsX_ - 1); ++x) {
      int inside = 0;
      for (int sy = 0; sy < kSamples; ++sy)
        for (int sx = 0; sx < kSamples; ++sx) {
          const double e = originEast_m_ + (x + (sx + 0.5) / kSamples) * kLightColumn_m;
          const double n = originNorth_m_ + (y + (sy + 0.5) / kSamples) * kLightColumn_m;
          const double de = e - crown.east_m, dn = n - crown.north_m;
          inside += de * de + dn * dn <= r * r ? 1 : 0;
        }
      if (inside == 0) continue;
      out.push_back({static_cast<std::int32_t>(static_cast<long>(y) * columnsX_ + x),
                     static_cast<float>(inside)});
      total += inside;
    }
  if (total == 0) {
    out.assign(1, {static_cast<std::int32_t>(columnAt(crown.east_m, crown.north_m)), 1.0f});
    return;
  }
  for (Footprint& f : out) f.weight /= static_cast<float>(total);
}

void LightGrid::compute(const std::vector<CrownShape>& crowns) {
  std::vector<float> east, north, radius, top, leafArea;
  std::vector<std::uint32_t> rows;
  for (const CrownShape& crown : crowns) {
    rows.push_back(static_cast<std::uint32_t>(rows.size()));
    east.push_back(crown.east_m);
    north.push_back(crown.north_m);
    radius.push_back(crown.radius_m);
    top.push_back(crown.top_m);
    leafArea.push_back(crown.leafArea_m2);
  }
  compute(CrownColumns{east, north, radius, top, rows, leafArea});
}

void LightGrid::compute(const CrownColumns& crowns) {
  const std::size_t n = crowns.size();
  const std::size_t columns = topLight_.size();
  // Each crown's footprint, in crown order (CSR), and each column's layers: count, then fill,
  // crown by crown side by side. A column's count is added to atomically, and its layers are
  // placed in whatever order the crowns come: the sort below orders them in full (by top,
  // then entry), so the light is the same whatever the thread count.
  resizeForOverwrite(crownStart_, n + 1);
  crownStart_[0] = 0;
  columnStart_.assign(columns + 1, 0);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    thread_local std::vector<Footprint> footprints;
    footprint(crowns[i], footprints);
    crownStart_[i + 1] = static_cast<std::uint32_t>(footprints.size());
    for (const Footprint& f : footprints)
      std::atomic_ref(columnStart_[f.column + 1]).fetch_add(1, std::memory_order_relaxed);
  });
  std::size_t entryCount = 0;
  for (std::size_t i = 0; i < n; ++i) {
    entryCount += crownStart_[i + 1];
    ECO_ASSERT(entryCount <= std::numeric_limits<std::uint32_t>::max(),
               "more crown footprint entries than 32 bits index");
    crownStart_[i + 1] = static_cast<std::uint32_t>(entryCount);
  }
  for (std::size_t c = 0; c < columns; ++c) columnStart_[c + 1] += columnStart_[c];
  resizeForOverwrite(entries_, entryCount);
  resizeForOverwrite(layers_, entryCount);
  std::vector<std::size_t> nextLayer(columnStart_.begin(), columnStart_.end() - 1);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    thread_local std::vector<Footprint> footprints;
    footprint(crowns[i], footprints);
    const float top = crowns.top_m[crowns.rows[i]];
    for (std::size_t k = 0; k < footprints.size(); ++k) {
      const std::uint32_t e = crownStart_[i] + static_cast<std::uint32_t>(k);
      entries_[e].share = {static_cast<std::uint32_t>(i), footprints[k].weight};
      Layer& layer = layers_[std::atomic_ref(nextLayer[footprints[k].column])
                                 .fetch_add(1, std::memory_order_relaxed)];
      layer.top_m = top;
      layer.entry = e;
    }
  });

  // Each column's layers, tallest crown first (ties: the earlier crown, whose entries come
  // first; a crown has one entry in a column).
  tbb::parallel_for(std::size_t{0}, columns, [&](std::size_t c) {
    Layer* first = layers_.data() + columnStart_[c];
    Layer* last = layers_.data() + columnStart_[c + 1];
    std::sort(first, last, [](const Layer& a, const Layer& b) {
      return a.top_m != b.top_m ? a.top_m > b.top_m : a.entry < b.entry;
    });
    double light = topLight_[c];
    for (Layer* layer = first; layer != last; ++layer) {
      Entry& entry = entries_[layer->entry];
      const CrownShape crown = crowns[entry.share.crown];
      const double area = std::min(kColumnArea_m2, crownArea(crown) * entry.share.weight);
      const double taken = area * light * absorbedShare(crown);
      entry.taken = taken;  // the share is read for the last time above
      light = std::max(0.0, light - taken / kColumnArea_m2);
      layer->lightBelow = static_cast<float>(light);  // the entry is read for the last time above
    }
  });
}

void LightGrid::releaseAbsorbed() {
  Buffer<std::uint32_t>().swap(crownStart_);
  Buffer<Entry>().swap(entries_);
}

double LightGrid::absorbed(std::size_t crown) const {
  ECO_ASSERT(crown + 1 < crownStart_.size(),
             "crown " << crown << " of " << crownStart_.size() << " entries' starts (released?)");
  double sum = 0.0;
  for (std::size_t e = crownStart_[crown]; e < crownStart_[crown + 1]; ++e)
    sum += entries_[e].taken;
  return sum;
}

double LightGrid::absorbedInTheOpen(const CrownShape& crown) {
  return crownArea(crown) * absorbedShare(crown);
}

double LightGrid::lightAt(double east_m, double north_m, double height_m) const {
  return lightInColumn(columnAt(east_m, north_m), height_m);
}

double LightGrid::lightInColumn(long column, double height_m) const {
  // The last crown whose top is above the height sets the light there.
  const Layer* begin = layersBegin(column);
  const Layer* end = layersEnd(column);
  const Layer* below =
      std::partition_point(begin, end, [&](const Layer& layer) { return layer.top_m > height_m; });
  return below == begin ? topLight_[column] : (below - 1)->lightBelow;
}

double LightGrid::groundLightAt(double east_m, double north_m) const {
  return groundLightInColumn(columnAt(east_m, north_m));
}

double LightGrid::groundLightInColumn(long column) const {
  return layersBegin(column) == layersEnd(column) ? topLight_[column]
                                                  : (layersEnd(column) - 1)->lightBelow;
}

double LightGrid::beyondCrown_m(double crownRadius_m) {
  return crownRadius_m + kLightColumn_m * std::numbers::sqrt2;
}

double LightGrid::heightWithSideLight(double east_m, double north_m, double reach_m, double from_m,
                                      double top_m, double light) const {
  const std::array<long, 4> columns{
      columnAt(east_m + reach_m, north_m), columnAt(east_m, north_m + reach_m),
      columnAt(east_m - reach_m, north_m), columnAt(east_m, north_m - reach_m)};
  // Walk up the four columns at once, from `from_m` through their crown tops, lowest first.
  // A column's layers above the current height are its first ones (tallest first), up to
  // `above`; the light there is the last of them's light below, and the next top up is that
  // layer's. The side light never falls with height, so the first height where it suffices
  // is the answer: one pass over the layers between the two heights, without gathering and
  // sorting the four columns' tops.
  // The layers above `from_m` are found from the shortest up: a crown's base lies below
  // nearly every top of the columns around it (about 0.3 of their 10 layers each, in a
  // landscape's late years), where a binary search took a few unpredictable steps.
  std::array<const Layer*, 4> tallest{}, above{};
  for (std::size_t c = 0; c < columns.size(); ++c) {
    tallest[c] = layersBegin(columns[c]);
    above[c] = layersEnd(columns[c]);
    while (above[c] != tallest[c] && !((above[c] - 1)->top_m > from_m)) --above[c];
  }
  double height = from_m;
  for (;;) {
    double sum = 0.0;
    for (std::size_t c = 0; c < columns.size(); ++c)
      sum += above[c] == tallest[c] ? topLight_[columns[c]] : (above[c] - 1)->lightBelow;
    if (0.25 * sum >= light) return height;
    float next = std::numeric_limits<float>::infinity();
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (above[c] != tallest[c]) next = std::min(next, (above[c] - 1)->top_m);
    if (!(next < top_m)) return top_m;
    height = next;
    for (std::size_t c = 0; c < columns.size(); ++c)
      while (above[c] != tallest[c] && (above[c] - 1)->top_m <= next) --above[c];
  }
}

}  // namespace eco
